! B-spline paraboloid z = (x^2 + y^2)/1.9168293127388174 (scripts/make_contact_inputs.py)
&bspline file = 'tower5_2.csv', layout = 'scattered', degree = 5, smoothing = 0.05 /

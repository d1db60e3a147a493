! B-spline paraboloid z = (x^2 + y^2)/1.224744871391589 (scripts/make_contact_inputs.py)
&bspline file = 'tower5_3.csv', layout = 'scattered', degree = 5, smoothing = 0.05 /

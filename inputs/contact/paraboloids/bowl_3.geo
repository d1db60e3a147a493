! B-spline paraboloid z = (x^2 + y^2)/0.5 (scripts/make_contact_inputs.py)
&bspline file = 'bowl_3.csv', layout = 'scattered', degree = 5, smoothing = 0.05 /

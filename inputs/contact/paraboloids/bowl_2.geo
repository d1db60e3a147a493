! B-spline paraboloid z = (x^2 + y^2)/3.0 (scripts/make_contact_inputs.py)
&bspline file = 'bowl_2.csv', layout = 'scattered', degree = 5, smoothing = 0.05 /

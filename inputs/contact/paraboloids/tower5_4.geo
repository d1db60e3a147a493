! B-spline paraboloid z = (x^2 + y^2)/0.7825422900366437 (scripts/make_contact_inputs.py)
&bspline file = 'tower5_4.csv', layout = 'scattered', degree = 5, smoothing = 0.05 /

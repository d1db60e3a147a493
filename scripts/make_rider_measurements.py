#!/usr/bin/python3
"""Makes the example rider measurements of inputs/design/identify_rider_demo.nml:
a twin run of slidesim (scenario identify_rider with &identify twin_mu, the
thesis's mu_D = 0.0724419, table 4.8) on the first 14 m of the demo slide
gives the wall angles of pelvis, heels and back where the pelvis crosses 7
stations and the pelvis's speed on 2 segments; Gaussian noise of 0.03 rad and
0.05 m/s (numpy's default_rng, seed 11) is added and the tables written to
inputs/design/rider_stations.csv and rider_segments.csv.

usage: scripts/make_rider_measurements.py [path/to/slidesim]   (from the repository root)
"""
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np

TWIN = """&run scenario = 'identify_rider', output = 'twin.h5' /
&surface kind = 'slide', geometry_file = 'builtin:demo_slide' /
&water flow_rate = 0.004, start = 'edges', u0 = 0.0, v_left0 = 1.9207963267948966,
  v_right0 = 1.2207963267948966, f1 = 0.0274748, f2 = 0.138285, f3 = 0.979822, correction = 'full' /
&rider mu = 0.0724419 /
&identify twin_mu = 0.0724419
  station_arc_length = 2.5, 4.4, 6.3, 8.2, 10.1, 12.0, 13.9
  segment_start = 3.0, 9.0
  segment_end = 5.0, 11.0 /
"""
SIGMA_ANGLE, SIGMA_SPEED, SEED = 0.03, 0.05, 11


def main(argv):
    slidesim = os.path.abspath(argv[1] if len(argv) > 1 else "build/app/slidesim")
    with tempfile.TemporaryDirectory() as work:
        with open(os.path.join(work, "twin.nml"), "w") as f:
            f.write(TWIN)
        subprocess.run([slidesim, "-q", "twin.nml"], cwd=work, check=True)
        with h5py.File(os.path.join(work, "twin.h5"), "r") as f:
            s = f["/identify_rider/stations/arc_length"][:]
            angle = f["/identify_rider/stations/measured_angle"][:]
            a = f["/identify_rider/segments/start"][:]
            b = f["/identify_rider/segments/end"][:]
            speed = f["/identify_rider/segments/measured_speed"][:]
    rng = np.random.default_rng(SEED)
    angle = angle + SIGMA_ANGLE * rng.standard_normal(angle.shape)
    speed = speed + SIGMA_SPEED * rng.standard_normal(speed.shape)
    head = "# made by scripts/make_rider_measurements.py: a twin ride with mu_D = 0.0724419, noise 0.03 rad, seed 11\n"
    with open("inputs/design/rider_stations.csv", "w") as f:
        f.write(head + "arc_length_m,pelvis_rad,heels_rad,back_rad\n")
        for k in range(len(s)):
            f.write(f"{s[k]:.4f},{angle[k, 0]:.6f},{angle[k, 1]:.6f},{angle[k, 2]:.6f}\n")
    with open("inputs/design/rider_segments.csv", "w") as f:
        f.write(head.replace("0.03 rad", "0.05 m/s") + "start_m,end_m,speed_m_s\n")
        for k in range(len(a)):
            f.write(f"{a[k]:.4f},{b[k]:.4f},{speed[k]:.6f}\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

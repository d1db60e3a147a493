"""Parses the meshes slidesim exports (--export-stl, --export-obj) and checks
them; no mesh library, the formats are read here.

    check_mesh.py tube FILE.stl FILE.obj RADIUS LENGTH N_V   a straight tube along x from 0
    check_mesh.py ride FILE.stl FILE.obj                   the demo ride: slide and water band

Prints failures; exit status 1 if any.
"""
import math
import sys
from collections import Counter

import numpy as np

failures = []


def fail(message):
    failures.append(message)


def read_stl(path):
    """{solid: (normals (n, 3), triangles (n, 3, 3))} of an ASCII STL."""
    solids, name, normals, corners = {}, None, [], []
    for number, line in enumerate(open(path, encoding='ascii'), 1):
        words = line.split()
        if not words:
            continue
        if words[0] == 'solid':
            name, normals, corners = words[1], [], []
        elif words[0] == 'facet':
            normals.append([float(w) for w in words[2:5]])
        elif words[0] == 'vertex':
            corners.append([float(w) for w in words[1:4]])
        elif words[0] == 'endsolid':
            if words[1] != name:
                fail(f"{path}:{number}: endsolid {words[1]} closes solid {name}")
            solids[name] = (np.array(normals), np.array(corners).reshape(-1, 3, 3))
        elif words[0] not in ('outer', 'endloop', 'endfacet'):
            fail(f"{path}:{number}: unexpected {line.strip()!r}")
    return solids


def read_obj(path):
    """{object: (vertices (n, 3), faces (m, 3) 0-based into them)}."""
    vertices, objects, name = [], {}, None
    faces = {}
    for number, line in enumerate(open(path, encoding='ascii'), 1):
        words = line.split()
        if not words or words[0] == '#':
            continue
        if words[0] == 'o':
            name = words[1]
            faces[name] = []
        elif words[0] == 'v':
            vertices.append([float(w) for w in words[1:4]])
        elif words[0] == 'f':
            faces[name].append([int(w) - 1 for w in words[1:4]])
        else:
            fail(f"{path}:{number}: unexpected {line.strip()!r}")
    vertices = np.array(vertices)
    for name, f in faces.items():
        f = np.array(f)
        if f.min() < 0 or f.max() >= len(vertices):
            fail(f"{path}: object {name}: a face names a vertex that does not exist")
        objects[name] = (vertices, f)
    return objects


def area_vectors(triangles):
    return 0.5 * np.cross(triangles[:, 1] - triangles[:, 0], triangles[:, 2] - triangles[:, 0])


def edges_check(name, triangles, boundary_ok):
    """Consistent orientation: vertices merged by position (1e-6 m), every
    edge in at most two triangles, an interior edge once each way; the
    boundary edges those boundary_ok(midpoint) allows."""
    keys = {}
    index = np.array([[keys.setdefault(tuple(np.round(p, 6)), len(keys)) for p in t] for t in triangles])
    directed = Counter()
    for a, b, c in index:
        for e in ((a, b), (b, c), (c, a)):
            if e[0] != e[1]:
                directed[e] += 1
    points = {v: k for k, v in keys.items()}
    for (a, b), count in directed.items():
        if count > 1:
            fail(f"{name}: edge {a}-{b} runs the same way in {count} triangles (orientation not consistent)")
        if (b, a) not in directed:
            middle = 0.5 * (np.array(points[a]) + np.array(points[b]))
            if not boundary_ok(middle):
                fail(f"{name}: a boundary edge at {middle} (a hole or a flipped triangle)")
                return


def check_stl_normals(name, normals, triangles):
    """Each facet's normal is the right-hand normal of its vertices."""
    vectors = area_vectors(triangles)
    length = np.linalg.norm(vectors, axis=1)
    ok = length > 1e-12
    unit = vectors[ok] / length[ok, None]
    if np.abs(unit - normals[ok]).max() > 1e-6:
        fail(f"{name}: a facet normal disagrees with its vertex order")


def tube(stl, obj, radius, length, n_v):
    solids, objects = read_stl(stl), read_obj(obj)
    if list(solids) != ['slide_surface'] or list(objects) != ['slide_surface']:
        fail(f"a geometry result: solids {list(solids)}, objects {list(objects)}, not ['slide_surface']")
        return
    normals, triangles = solids['slide_surface']
    vertices, faces = objects['slide_surface']
    if len(faces) != len(triangles) or np.abs(vertices[faces] - triangles).max() > 1e-6:
        fail("the OBJ's triangles are not the STL's")
    check_stl_normals('tube', normals, triangles)
    area = np.linalg.norm(area_vectors(triangles), axis=1).sum()
    segments = n_v - 1
    # every quad of a straight tube is a plane rectangle: chord x its length, so
    # the triangles' area is exactly segments * chord * L (up to the file's nine digits)
    polygon = segments * 2 * radius * math.sin(math.pi / segments) * length
    if abs(area - polygon) > 1e-7 * polygon:
        fail(f"tube: area {area!r}, the inscribed polygon's {polygon!r}")
    # against 2 pi r L: the chords fall short by (pi/n)^2/6 to leading order
    cylinder = 2 * math.pi * radius * length
    deficit = (cylinder - area) / cylinder
    expected = (math.pi / segments) ** 2 / 6
    if not 0.99 * expected <= deficit <= 1.01 * expected:
        fail(f"tube: area {area} against 2 pi r L = {cylinder}: short by {deficit:.3e}, the chords' "
             f"(pi/n)^2/6 = {expected:.3e}")
    # outwards: away from the axis (the x axis)
    centres = triangles.mean(axis=1)
    radial = centres.copy()
    radial[:, 0] = 0
    if (np.einsum('ij,ij->i', normals, radial) <= 0).any():
        fail("tube: a triangle faces the axis (not outwards)")
    edges_check('tube', triangles, lambda m: abs(m[0]) < 1e-6 or abs(m[0] - length) < 1e-6)
    print(f"tube: {len(triangles)} triangles, area {area:.9f} m^2, 2 pi r L {cylinder:.9f} m^2, "
          f"short by {deficit:.3e} (chords: {expected:.3e})")


def ride(stl, obj):
    solids, objects = read_stl(stl), read_obj(obj)
    if list(solids) != ['slide_surface', 'water_band'] or list(objects) != list(solids):
        fail(f"a ride: solids {list(solids)}, objects {list(objects)}, not slide and water")
        return
    for name in solids:
        normals, triangles = solids[name]
        check_stl_normals(name, normals, triangles)
        vertices, faces = objects[name]
        if len(faces) != len(triangles) or np.abs(vertices[faces] - triangles).max() > 1e-6:
            fail(f"{name}: the OBJ's triangles are not the STL's")
    normals, triangles = solids['water_band']
    if (normals[:, 2] < 0).mean() > 0.01:
        fail("water band: more than 1 % of its triangles face down")
    print(f"ride: slide {len(solids['slide_surface'][1])} triangles, water {len(triangles)} triangles")


if __name__ == '__main__':
    kind = sys.argv[1]
    if kind == 'tube':
        tube(sys.argv[2], sys.argv[3], float(sys.argv[4]), float(sys.argv[5]), int(sys.argv[6]))
    else:
        ride(sys.argv[2], sys.argv[3])
    for line in failures:
        print('FAIL ' + line)
    sys.exit(1 if failures else 0)

"""Checks the XDMF files slidesim writes next to its results.

    check_xdmf.py [--docs OUTPUTS.md] FILE.xmf [...]              the structure (h5py, numpy)
    pvpython check_xdmf.py --paraview [--docs OUTPUTS.md] FILE.xmf [...]   also opens each in ParaView

    check_xdmf.py --same-values OLD.xmf NEW.xmf                     the same numbers in two views

Structure: the XML parses; every DataItem is inline XML or a reference to a
dataset of the result file beside the .xmf, named by the result's file name
without folder (`NAME.h5:/path`; never a temporary file's name), which
exists (h5py) with as many values as the DataItem's Dimensions say and of its
NumberType (8-byte reals, 4-byte integers); every inline DataItem holds as
many numbers as its Dimensions say; every grid's geometry has as many points as its topology has nodes,
every connectivity index names one of them, every node attribute has as
many values as points and every cell attribute as cells; a temporal
collection's times increase, and its later steps include (xi:include) the
first step's fixed grids; a surface grid has exactly the points of the
result's /geometry/surface, a band exactly the rows of its two edges and
each field twice over. With --docs, the grids against the table of
docs/outputs.md ("ParaView and VisIt"): every grid of a file is listed there
for the file's scenario, and every grid listed for a scenario is in some
file of that scenario among those checked.

With --paraview (run by pvpython): ParaView opens each file with the reader
it picks by itself (OpenDataFile, as File > Open), which must be one of the
readers named below; it must show the file's number of time steps, the
arrays the file describes, and at the first and the last step the number of
points the file describes. A crash (ParaView's Xdmf3 readers abort on what
they cannot read) fails the whole check. Prints failures; exit status 1 if any.
"""
import os
import re
import sys
import xml.etree.ElementTree as ET

import numpy as np

failures = []
XINCLUDE = '{http://www.w3.org/2001/XInclude}include'
# readers ParaView 5.11 picks by itself for .xmf (Xdmf3ReaderS first)
DEFAULT_READERS = {'Xdmf3ReaderS', 'Xdmf3ReaderT', 'XdmfReader'}


def fail(path, message):
    failures.append(f"{path}: {message}")


def dims(item):
    return [int(d) for d in item.get('Dimensions').split()]


# the result file beside the .xmf being checked: {'name': file name, 'file': h5py.File}
beside = {}


def referenced(path, item):
    """The values of the dataset an HDF DataItem names, or None."""
    reference = item.text.strip()
    name, _, dataset = reference.partition(':')
    if name != beside['name']:
        fail(path, f"DataItem names {reference!r}, not a dataset of {beside['name']} beside it")
        return None
    if dataset not in beside['file'] or not hasattr(beside['file'][dataset], 'dtype'):
        fail(path, f"DataItem names {reference!r}, which {beside['name']} does not hold")
        return None
    data = beside['file'][dataset]
    wanted = {('Float', '8'): np.float64, ('Int', '4'): np.int32}.get((item.get('NumberType'), item.get('Precision')))
    if wanted is None or data.dtype != wanted:
        fail(path, f"DataItem {reference!r} of {item.get('NumberType')} {item.get('Precision')}: the dataset is "
                   f"{data.dtype}")
    return np.asarray(data[()], dtype=float).ravel()


def values(path, item):
    """The numbers of a DataItem (inline or referenced), checked against its Dimensions."""
    if item.get('ItemType', 'Uniform') != 'Uniform' or item.get('Format') not in ('XML', 'HDF'):
        fail(path, f"DataItem neither inline XML nor a dataset: {item.attrib}")
        return np.zeros(0)
    if item.get('Format') == 'HDF':
        numbers = referenced(path, item)
        if numbers is None:
            return np.zeros(0)
    else:
        numbers = np.array(item.text.split(), dtype=float)
    if numbers.size != int(np.prod(dims(item))):
        fail(path, f"DataItem of Dimensions {dims(item)} holds {numbers.size} numbers")
    if not np.all(np.isfinite(numbers)):
        fail(path, "DataItem holds a number that is not finite")
    return numbers


def check_uniform(path, grid):
    """Checks one uniform grid; returns (points, cells, attribute names, xyz)."""
    name = grid.get('Name')
    topology = grid.find('Topology')
    kind = topology.get('TopologyType')
    xyz = values(path, grid.find('Geometry').find('DataItem')).reshape(-1, 3)
    n = len(xyz)
    if kind == '2DSMesh':
        shape = dims(topology)
        if int(np.prod(shape)) != n:
            fail(path, f"grid {name}: {n} points, topology {shape}")
        cells = (shape[0] - 1) * (shape[1] - 1)
    elif kind in ('Polyline', 'Polyvertex', 'Triangle'):
        per = {'Triangle': 3}.get(kind, int(topology.get('NodesPerElement', 0)))
        cells = int(topology.get('NumberOfElements'))
        item = topology.find('DataItem')
        if item is None:   # the Xdmf3 readers make no cell without a connectivity
            fail(path, f"grid {name}: {kind} without connectivity")
        else:
            connectivity = values(path, item)
            if connectivity.size != cells * per:
                fail(path, f"grid {name}: {connectivity.size} indices for {cells} cells of {per}")
            if connectivity.size and (connectivity.min() < 0 or connectivity.max() >= n):
                fail(path, f"grid {name}: a connectivity index outside its {n} points")
    else:
        fail(path, f"grid {name}: unexpected topology {kind}")
        cells = 0
    names = []
    for attribute in grid.findall('Attribute'):
        per = {'Scalar': 1, 'Vector': 3}[attribute.get('AttributeType')]
        count = {'Node': n, 'Cell': cells}[attribute.get('Center')]
        size = values(path, attribute.find('DataItem')).size
        if size != per * count:
            fail(path, f"grid {name}: attribute {attribute.get('Name')} has {size} values for {count} "
                       f"{attribute.get('Center').lower()}s")
        names.append(attribute.get('Name'))
    return n, cells, names, xyz


def documented_grids(docs):
    """The grid table of docs/outputs.md: [(name regex, source name, {scenarios})]."""
    text = open(docs, encoding='utf-8').read()
    section = text.split('## ParaView and VisIt', 1)[1].split('\n## ', 1)[0]
    rows = []
    for line in section.splitlines():
        cells = [c.strip() for c in line.strip().strip('|').split('|')]
        if not line.startswith('| `') or len(cells) < 3:
            continue
        scenarios = {x.strip() for x in cells[1].split(',')}
        for name in re.findall(r'`([^`]+)`', cells[0]):
            pattern = re.sub(r'<[^>]+>', '.+', re.escape(name).replace(r'\<', '<').replace(r'\>', '>'))
            rows.append((re.compile(pattern + '$'), name, scenarios))
    return rows


def check_docs(docs, grids_of):
    """grids_of: {path: (scenario, [grid names])}."""
    rows = documented_grids(docs)
    seen = set()
    for path, (scenario, names) in grids_of.items():
        for name in names:
            matches = [(r, n) for r, n, scenarios in rows if scenario in scenarios and r.match(name)]
            if not matches:
                fail(path, f"grid {name!r}: not listed for scenario {scenario} in {docs}")
            seen.update((n, scenario) for _, n in matches)
    checked = {scenario for scenario, _ in grids_of.values()}
    for _, name, scenarios in rows:
        for scenario in scenarios & checked:
            if (name, scenario) not in seen:
                fail(docs, f"grid {name!r} listed for {scenario}, but no {scenario} file checked has it")


def check_surface(path, name, xyz):
    """A surface grid holds the result's surface points (the same numbers)."""
    h5 = beside['file']
    if '/geometry/surface/x' not in h5:
        fail(path, f"grid {name}: the result has no /geometry/surface")
        return
    expected = np.stack([h5['/geometry/surface/' + c][()].ravel() for c in 'xyz'], axis=1)
    if expected.shape != xyz.shape or not np.array_equal(expected, xyz):
        fail(path, f"grid {name}: its points are not the result's /geometry/surface")


def check_band(path, grid):
    """The water band holds the rows of the result's two edges and each field twice over."""
    h5 = beside['file']
    n, _, names, xyz = check_uniform(path, grid)
    edges = [h5[f'/water/{edge}_point'][()] for edge in ('right', 'left') if f'/water/{edge}_point' in h5]
    if len(edges) != 2 or not np.array_equal(xyz, np.concatenate(edges)):
        fail(path, f"grid {grid.get('Name')}: its points are not /water/right_point then /water/left_point")
    for attribute in grid.findall('Attribute'):
        field = attribute.get('Name')
        got = values(path, attribute.find('DataItem'))
        if f'/water/{field}' not in h5 or not np.array_equal(got, np.tile(h5[f'/water/{field}'][()], 2)):
            fail(path, f"grid {grid.get('Name')}: {field} is not /water/{field} twice over")


def check(path):
    """Checks one XDMF file; returns a dict: points at the first and last
    step, steps, arrays, scenario, top-level grid names."""
    import h5py
    root = ET.parse(path).getroot()
    h5_path = os.path.join(os.path.dirname(path), os.path.basename(path)[:-4] + '.h5')
    if beside:
        beside['file'].close()
    beside.update(name=os.path.basename(h5_path), file=h5py.File(h5_path, 'r'))
    domain = root.find('Domain')
    collections = [g for g in domain.findall('Grid') if g.get('CollectionType') == 'Temporal']
    arrays = set()
    if collections:
        if len(domain.findall('Grid')) != 1:
            fail(path, "a temporal collection beside other grids (the Xdmf3 readers drop those)")
        steps = collections[0].findall('Grid')
        times = [float(step.find('Time').get('Value')) for step in steps]
        if any(b <= a for a, b in zip(times, times[1:])):
            fail(path, "time steps not increasing")
        first = steps[0].findall('Grid')
        fixed_count = len(steps[1].findall(XINCLUDE)) if len(steps) > 1 else 0
        fixed_points = 0
        for grid in first[:fixed_count]:
            n, _, names_of, _ = check_uniform(path, grid)
            fixed_points += n
            arrays.update(names_of)
        counts = []
        for s, step in enumerate(steps):
            includes = step.findall(XINCLUDE)
            own = step.findall('Grid')[fixed_count if s == 0 else 0:]
            if s > 0 and (len(includes) != fixed_count or len(own) != len(first) - fixed_count):
                fail(path, f"step {s + 1}: {len(includes)} included and {len(own)} own grids, the first step "
                           f"{fixed_count} fixed and {len(first) - fixed_count} moving")
            for k, include in enumerate(includes):
                wanted = f"xpointer(/Xdmf/Domain/Grid/Grid[1]/Grid[{k + 1}])"
                if include.get('xpointer') != wanted:
                    fail(path, f"step {s + 1}: includes {include.get('xpointer')}, not {wanted}")
            points = fixed_points
            for grid in own:
                n, _, names_of, _ = check_uniform(path, grid)
                points += n
                arrays.update(names_of)
            counts.append(points)
        names = [g.get('Name') for g in first]
        grids_for_surface = first
        result = {'points': (counts[0], counts[-1]), 'steps': len(steps)}
    else:
        grids_for_surface = domain.findall('Grid')
        points = 0
        for grid in grids_for_surface:
            n, _, names_of, _ = check_uniform(path, grid)
            points += n
            arrays.update(names_of)
        names = [g.get('Name') for g in grids_for_surface]
        result = {'points': (points, points), 'steps': 0}
    for grid in grids_for_surface:
        if 'surface' in grid.get('Name'):
            check_surface(path, grid.get('Name'), check_uniform(path, grid)[3])
        if grid.get('Name') == 'water band':
            check_band(path, grid)
    h5 = beside['file']
    if '/geometry/surface/x' in h5 and not any('surface' in name for name in names):
        fail(path, "the result has a surface grid, the XDMF file none")
    scenario = h5.attrs['scenario']
    result.update(arrays=arrays, scenario=scenario, names=names)
    return result


def open_in_paraview(path, expected):
    """Opens `path` as File > Open does; compares with the file's own description."""
    from paraview.simple import OpenDataFile, Delete
    reader = OpenDataFile(path)
    if reader is None:
        fail(path, "ParaView has no reader for it")
        return
    name = reader.GetXMLName()
    if name not in DEFAULT_READERS:
        fail(path, f"ParaView picked the reader {name}")
    reader.UpdatePipelineInformation()
    times = list(reader.TimestepValues or [])
    if len(times) != expected['steps']:
        fail(path, f"ParaView shows {len(times)} time steps, the file has {expected['steps']}")
    shown_arrays = set()
    for k, t in enumerate(times[:1] + times[-1:] if times else [0.0]):
        reader.UpdatePipeline(t)
        info = reader.GetDataInformation()
        shown = info.GetNumberOfPoints()
        wanted = expected['points'][min(k, 1)]
        if shown != wanted:
            fail(path, f"{name} shows {shown} points at t = {t}, the file describes {wanted}")
        shown_arrays.update(reader.PointData.keys())
        shown_arrays.update(reader.CellData.keys())
    if shown_arrays != expected['arrays']:
        fail(path, f"{name} shows the arrays {sorted(shown_arrays)}, the file has {sorted(expected['arrays'])}")
    Delete(reader)
    print(f"{os.path.basename(path)}: {name}, {len(times)} steps, {len(shown_arrays)} arrays")


def resolved_items(path):
    """Every DataItem of a view in document order: (where, numbers)."""
    import h5py
    h5_path = os.path.join(os.path.dirname(path), os.path.basename(path)[:-4] + '.h5')
    if beside:
        beside['file'].close()
    beside.update(name=os.path.basename(h5_path), file=h5py.File(h5_path, 'r'))
    items = []

    def walk(element, where):
        for child in element:
            if child.tag == 'DataItem':
                items.append((where, values(path, child)))
            elif child.tag != XINCLUDE:
                walk(child, where + '/' + child.tag + (f"[{child.get('Name')}]" if child.get('Name') else ''))
    walk(ET.parse(path).getroot(), '')
    return items


def same_values(old, new):
    """The two views describe the same grids with the same numbers (the old
    inline ones have nine significant digits: half a unit of the ninth)."""
    a, b = resolved_items(old), resolved_items(new)
    if [w for w, _ in a] != [w for w, _ in b]:
        fail(new, f"not the DataItems of {old}")
        return
    for (where, x), (_, y) in zip(a, b):
        if x.shape != y.shape or np.any(np.abs(x - y) > 5.0000001e-9 * np.maximum(np.abs(y), 1e-300)):
            fail(new, f"{where}: not the numbers of {old}")
    print(f"{new}: {len(b)} DataItems, the numbers of {old}")


def main(args):
    if args[:1] == ['--same-values']:
        same_values(args[1], args[2])
        for line in failures:
            print('FAIL ' + line)
        sys.exit(1 if failures else 0)
    paraview = bool(args) and args[0] == '--paraview'
    paths = args[1:] if paraview else args
    docs = None
    if paths[:1] == ['--docs']:
        docs, paths = paths[1], paths[2:]
    checked = {path: check(path) for path in paths}
    if docs:
        check_docs(docs, {path: (c['scenario'], c['names']) for path, c in checked.items()})
    if paraview:
        for path in paths:
            open_in_paraview(path, checked[path])
    for line in failures:
        print('FAIL ' + line)
    print(f"{len(paths)} XDMF files checked{' and opened in ParaView' if paraview else ''}, "
          f"{len(failures)} failures")
    sys.exit(1 if failures else 0)


if __name__ == '__main__':
    main(sys.argv[1:])

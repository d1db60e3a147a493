"""Checks the XDMF files slidesim writes next to its results.

    check_xdmf.py [--docs OUTPUTS.md] FILE.xmf [...]              the structure, with h5py
    pvbatch check_xdmf.py --paraview [--docs OUTPUTS.md] FILE.xmf [...]   also opens each in ParaView

Structure: the XML parses; every HDF DataItem names the HDF5 file beside it
and a dataset that exists there with exactly the stated dimensions; every
HyperSlab selects rows inside its dataset; every JOIN function's size is the
sum of its parts; every grid's geometry has as many points as its topology
has nodes, and every node attribute as many values; temporal collections have
increasing times; a result with a surface grid has a surface grid in its
XDMF. With --docs, the grids against the table of docs/outputs.md ("ParaView
and VisIt"): every grid of a file is listed there for the file's scenario,
and every grid listed for a scenario is in some file of that scenario among
those checked. With --paraview, ParaView's XDMF reader loads each file and shows, at
the first time step, the number of points the structure says. Prints
failures; exit status 1 if any.
"""
import os
import re
import sys
import xml.etree.ElementTree as ET

import h5py
import numpy as np

failures = []


def fail(path, message):
    failures.append(f"{path}: {message}")


def dims(item):
    return [int(d) for d in item.get('Dimensions').split()]


def item_size(path, item, h5):
    """Checks a DataItem and returns its number of values."""
    kind = item.get('ItemType', 'Uniform')
    stated = dims(item)
    if kind == 'Uniform':
        if item.get('Format') == 'XML':
            return int(np.prod(stated))
        file_name, dataset = item.text.strip().split(':', 1)
        if file_name != h5.filename.rsplit('/', 1)[-1]:
            fail(path, f"DataItem refers to {file_name}, not the result beside it")
        elif dataset not in h5:
            fail(path, f"dataset {dataset} does not exist in {file_name}")
        elif list(h5[dataset].shape) != stated:
            fail(path, f"{dataset}: Dimensions {stated}, the dataset has {list(h5[dataset].shape)}")
        return int(np.prod(stated))
    if kind == 'HyperSlab':
        selection, source = list(item)
        values = [int(v) for v in selection.text.split()]
        rank = len(values) // 3
        start, stride, count = values[:rank], values[rank:2 * rank], values[2 * rank:]
        item_size(path, source, h5)
        extent = dims(source)
        for k in range(rank):
            if start[k] < 0 or start[k] + (count[k] - 1) * stride[k] >= extent[k]:
                fail(path, f"HyperSlab {values} outside {source.text.strip()} {extent}")
        if int(np.prod(count)) != int(np.prod(stated)):
            fail(path, f"HyperSlab selects {count}, states {stated}")
        return int(np.prod(stated))
    if kind == 'Function':
        function = item.get('Function')
        parts = [item_size(path, child, h5) for child in item]
        if function.startswith('JOIN('):
            used = [int(token.strip().lstrip('$')) for token in function[5:-1].split(';')]
            total = sum(parts[k] for k in used)
            if total != int(np.prod(stated)):
                fail(path, f"{function}: parts of {total} values, states {stated}")
        else:
            fail(path, f"unexpected function {function}")
        return int(np.prod(stated))
    fail(path, f"unexpected ItemType {kind}")
    return 0


def nodes(path, topology):
    kind = topology.get('TopologyType')
    if kind == '2DSMesh':
        return int(np.prod(dims(topology)))
    if kind in ('Polyline', 'Polyvertex'):
        return int(topology.get('NodesPerElement')) * int(topology.get('NumberOfElements'))
    fail(path, f"unexpected topology {kind}")
    return 0


def check_uniform(path, grid, h5):
    """Checks one uniform grid and returns its number of points."""
    n = nodes(path, grid.find('Topology'))
    geometry = grid.find('Geometry')
    sizes = [item_size(path, item, h5) for item in geometry.findall('DataItem')]
    points = sum(sizes) // 3 if geometry.get('GeometryType') == 'XYZ' else sizes[0]
    if points != n:
        fail(path, f"grid {grid.get('Name')}: {points} points, topology has {n} nodes")
    for attribute in grid.findall('Attribute'):
        size = item_size(path, attribute.find('DataItem'), h5)
        per_node = {'Scalar': 1, 'Vector': 3}[attribute.get('AttributeType')]
        if size != per_node * n:
            fail(path, f"grid {grid.get('Name')}: attribute {attribute.get('Name')} has {size} values "
                       f"for {n} nodes")
    return n


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


def check(path):
    """Checks one XDMF file; returns (the points ParaView should show at t0,
    the scenario, the top-level grid names)."""
    root = ET.parse(path).getroot()
    h5_path = os.path.join(os.path.dirname(path), os.path.basename(path)[:-4] + '.h5')
    h5 = h5py.File(h5_path, 'r')
    points = 0
    names = []
    for grid in root.find('Domain').findall('Grid'):
        names.append(grid.get('Name'))
        if grid.get('GridType') == 'Collection':
            times = [float(g.find('Time').get('Value')) for g in grid.findall('Grid')]
            if any(b <= a for a, b in zip(times, times[1:])):
                fail(path, f"collection {grid.get('Name')}: times not increasing")
            counts = [check_uniform(path, g, h5) for g in grid.findall('Grid')]
            points += counts[0]
        else:
            points += check_uniform(path, grid, h5)
    if '/geometry/surface/x' in h5 and not any('surface' in name for name in names):
        fail(path, "the result has a surface grid, the XDMF file none")
    scenario = h5.attrs['scenario']
    h5.close()
    return points, scenario, names


def main(args):
    paraview = bool(args) and args[0] == '--paraview'
    paths = args[1:] if paraview else args
    docs = None
    if paths[:1] == ['--docs']:
        docs, paths = paths[1], paths[2:]
    checked = {path: check(path) for path in paths}
    expected = {path: points for path, (points, _, _) in checked.items()}
    if docs:
        check_docs(docs, {path: (scenario, names) for path, (_, scenario, names) in checked.items()})
    if paraview:
        from paraview.simple import XDMFReader, Delete
        for path in paths:
            reader = XDMFReader(FileNames=[path])
            reader.UpdatePipelineInformation()
            times = reader.TimestepValues
            reader.UpdatePipeline(times[0] if times else 0.0)
            shown = reader.GetDataInformation().GetNumberOfPoints()
            if shown != expected[path]:
                fail(path, f"ParaView shows {shown} points, the file describes {expected[path]}")
            Delete(reader)
    for line in failures:
        print('FAIL ' + line)
    print(f"{len(paths)} XDMF files checked{' and opened in ParaView' if paraview else ''}, "
          f"{len(failures)} failures")
    sys.exit(1 if failures else 0)


if __name__ == '__main__':
    main(sys.argv[1:])

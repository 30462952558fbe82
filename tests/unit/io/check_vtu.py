#!/usr/bin/python3
"""Reads files written by altfem's VTU/PVD writer back with independent readers and
compares them with what the C++ test expected. Exit code 0 = match, 1 = mismatch or
a reader failed (meshio missing is a failure: the test must not pass without it),
77 = the optional reader (python3-vtk9) is not installed.

  check_vtu.py vtu FILE.vtu EXPECTED.json   meshio: points, per-cell types and point
                                            ids (faces for polyhedra), counts per
                                            type, point data, cell data
  check_vtu.py raw FILE.vtu EXPECTED.json   decodes the appended arrays named in
                                            EXPECTED["arrays"] itself (for what meshio
                                            cannot read, e.g. polyhedra mixed with
                                            other cells) and compares them
  check_vtu.py pvd FILE.pvd EXPECTED.json   the DataSet entries, and each frame via meshio
  check_vtu.py vtk FILE.vtu EXPECTED.json   python3-vtk9: point count, cell types, points
"""
import collections
import json
import pathlib
import sys
import xml.etree.ElementTree as ElementTree


class Mismatch(Exception):
    pass


def expect(condition, message):
    if not condition:
        raise Mismatch(message)


def check_meshio(file, expected):
    import meshio
    import numpy as np
    from meshio._vtk_common import meshio_to_vtk_type

    mesh = meshio.read(file)
    points = np.array(expected["points"], dtype=float)
    expect(np.array_equal(mesh.points, points), f"points differ:\n{mesh.points}\nexpected\n{points}")

    read_cells = []
    for block in mesh.cells:
        if block.type.startswith("polyhedron"):
            read_cells += [{"type": 42, "faces": [list(map(int, face)) for face in cell]} for cell in block.data]
        else:
            vtk_type = meshio_to_vtk_type[block.type]
            read_cells += [{"type": vtk_type, "points": list(map(int, cell))} for cell in block.data]
    expect(len(read_cells) == len(expected["cells"]),
           f"{len(read_cells)} cells read, expected {len(expected['cells'])}")
    for index, (read, wanted) in enumerate(zip(read_cells, expected["cells"])):
        expect(read == wanted, f"cell {index}: read {read}, expected {wanted}")
    counts = collections.Counter(str(cell["type"]) for cell in read_cells)
    expect(counts == collections.Counter(expected["cell_counts"]),
           f"cells per type {dict(counts)}, expected {expected['cell_counts']}")

    cell_count = len(read_cells)
    for kind, read_data in (("point_data", mesh.point_data), ("cell_data", mesh.cell_data)):
        wanted_data = expected.get(kind, {})
        expect(set(read_data) == set(wanted_data), f"{kind} names {sorted(read_data)}, expected {sorted(wanted_data)}")
        for name, wanted in wanted_data.items():
            wanted = np.array(wanted, dtype=float)
            read = read_data[name]
            if kind == "cell_data":  # meshio splits cell data by cell block
                read = np.concatenate([np.asarray(block).reshape(len(block), -1) for block in read])
                expect(read.shape[0] == cell_count, f"cell data '{name}' has {read.shape[0]} rows")
            read = np.asarray(read).reshape(wanted.shape[0], -1)
            expect(np.array_equal(read, wanted), f"{kind} '{name}' differs:\n{read}\nexpected\n{wanted}")


def raw_arrays(file):
    """Every DataArray of a binary-appended, raw, UInt64-header, little-endian VTU, by name."""
    import numpy as np

    content = pathlib.Path(file).read_bytes()
    start = content.index(b'<AppendedData encoding="raw">')
    block = content[content.index(b"_", start) + 1:]
    header = ElementTree.fromstring(content[:start].decode() + "</VTKFile>")
    expect(header.get("header_type") == "UInt64" and header.get("byte_order") == "LittleEndian",
           f"header attributes {header.attrib}")
    types = {"Float64": "<f8", "Int64": "<i8", "UInt8": "u1"}
    arrays = {}
    for array in header.iter("DataArray"):
        expect(array.get("format") == "appended", f"array {array.get('Name')} is not appended")
        offset = int(array.get("offset"))
        size = int(np.frombuffer(block[offset:offset + 8], "<u8")[0])
        arrays[array.get("Name")] = (np.frombuffer(block[offset + 8:offset + 8 + size], types[array.get("type")]),
                                     array.attrib)
    return arrays


def check_raw(file, expected):
    import numpy as np

    arrays = raw_arrays(file)
    for name, wanted in expected["arrays"].items():
        expect(name in arrays, f"no array '{name}' in {sorted(arrays)}")
        values, attributes = arrays[name]
        expect(np.array_equal(values, np.array(wanted)), f"array '{name}' is {values}, expected {wanted}")
    for name in expected.get("without_components", []):
        expect("NumberOfComponents" not in arrays[name][1], f"array '{name}' has NumberOfComponents")


def check_pvd(file, expected):
    root = ElementTree.parse(file).getroot()
    expect(root.get("type") == "Collection", f"VTKFile type {root.get('type')}")
    datasets = root.findall("./Collection/DataSet")
    expect(len(datasets) == len(expected["datasets"]), f"{len(datasets)} DataSets, expected {len(expected['datasets'])}")
    for read, wanted in zip(datasets, expected["datasets"]):
        expect(float(read.get("timestep")) == wanted["timestep"], f"timestep {read.get('timestep')} != {wanted['timestep']}")
        expect(int(read.get("part")) == wanted["part"], f"part {read.get('part')} != {wanted['part']}")
        expect(read.get("file") == wanted["file"], f"file {read.get('file')} != {wanted['file']}")
        check_meshio(pathlib.Path(file).parent / read.get("file"), wanted["content"])


def check_vtk(file, expected):
    try:
        import vtk
        from vtk.util.numpy_support import vtk_to_numpy
    except ImportError:
        print("python3-vtk9 is not installed: skipped", file=sys.stderr)
        sys.exit(77)
    import numpy as np

    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(str(file))
    reader.Update()
    grid = reader.GetOutput()
    points = np.array(expected["points"], dtype=float)
    expect(grid.GetNumberOfPoints() == len(points), f"{grid.GetNumberOfPoints()} points, expected {len(points)}")
    expect(np.array_equal(vtk_to_numpy(grid.GetPoints().GetData()), points), "points differ")
    types = [grid.GetCellType(cell) for cell in range(grid.GetNumberOfCells())]
    expect(types == [cell["type"] for cell in expected["cells"]], f"cell types {types}")


def main():
    if len(sys.argv) != 4 or sys.argv[1] not in ("vtu", "raw", "pvd", "vtk"):
        print(__doc__, file=sys.stderr)
        return 1
    mode, file, expected_file = sys.argv[1:]
    expected = json.loads(pathlib.Path(expected_file).read_text())
    try:
        {"vtu": check_meshio, "raw": check_raw, "pvd": check_pvd, "vtk": check_vtk}[mode](file, expected)
    except Mismatch as mismatch:
        print(f"{file}: {mismatch}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())

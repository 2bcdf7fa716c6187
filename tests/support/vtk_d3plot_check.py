#!/usr/bin/python3
"""IMPACT-3D's independent reader check: opens a d3plot database with VTK's vtkLSDynaReader
(Debian package python3-vtk9) and reports what VTK sees, so that the tests can compare it with
IMPACT-3D's own reader.

  /usr/bin/python3 tests/support/vtk_d3plot_check.py ROOT [--expect-nodes N] [--expect-solids N]
      [--expect-shells N] [--expect-beams N] [--expect-steps N] [--node-xyz X,Y,Z] [--all] [--json FILE] [--quiet-cells]
      [--ghost-deleted]

Output: the counts, the state times, the part names ("parts: [...]"), per state and part the
point and cell counts, per cell its arrays (unless --quiet-cells), and for the nodes chosen with
--node-xyz (initial position) or --all one line per state:
  STEP TIME PART INDEX USERID (initial) -> (position) | (displacement) | (velocity) | TEMPERATURE
The last line is "RESULT: OK" or "RESULT: FAIL"; the exit status is 0 or 1.  FAIL when VTK
printed an error, found no nodes or no states, or a count differs from an --expect-* value.
Exit status 77 (the CTest skip code) when VTK cannot be imported.

VTK's reader gives one block per part holding only that part's points, so node numbers are not
visible; a node is chosen by its initial coordinates.  The reader is run with DeformedMesh off:
the points are the initial geometry and the array "Deflected Coordinates" holds the current
positions.  Deleted solids are left out by VTK unless --ghost-deleted keeps them, flagged in
the array vtkGhostType.
"""
import argparse
import json
import math
import sys

try:
    from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow, vtkVersion
    from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet
    from vtkmodules.vtkIOLSDyna import vtkLSDynaReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
except ImportError as e:  # not installed: the caller skips
    print(f"VTK not available ({e}): check skipped")
    sys.exit(77)

CELL_KINDS = ("Point", "Beam", "Shell", "Thick Shell", "Solid", "Rigid Body", "Road Surface")


def as_array(attributes, name):
    a = attributes.GetArray(name)
    return None if a is None else vtk_to_numpy(a)


def triple(v):
    return None if v is None else "(" + ", ".join(f"{float(x):.6g}" for x in v) + ")"


def part_blocks(output):
    for i in range(output.GetNumberOfBlocks()):
        block = output.GetBlock(i)
        if block is None:
            continue
        name = output.GetMetaData(i).Get(vtkMultiBlockDataSet.NAME()) if output.HasMetaData(i) else f"block{i}"
        yield name, block


def parse_args():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("root", help="the d3plot root file")
    p.add_argument("--node-xyz", help="choose the node(s) at this initial position X,Y,Z")
    p.add_argument("--all", action="store_true", help="list every node (small models)")
    p.add_argument("--json", help="write what was read (per state and part) to this file")
    p.add_argument("--quiet-cells", action="store_true", help="no line per cell")
    p.add_argument("--ghost-deleted", action="store_true", help="keep deleted cells, flagged in vtkGhostType")
    p.add_argument("--expect-nodes", type=int)
    p.add_argument("--expect-solids", type=int)
    p.add_argument("--expect-shells", type=int)
    p.add_argument("--expect-beams", type=int)
    p.add_argument("--expect-steps", type=int)
    return p.parse_args()


def main():
    args = parse_args()
    messages = vtkStringOutputWindow()
    vtkOutputWindow.SetInstance(messages)

    reader = vtkLSDynaReader()
    readable = reader.CanReadFile(args.root)
    reader.SetFileName(args.root)
    reader.SetDeformedMesh(0)
    if args.ghost_deleted:
        reader.SetDeletedCellsAsGhostArray(1)
    reader.UpdateInformation()

    nodes, solids = reader.GetNumberOfNodes(), reader.GetNumberOfSolidCells()
    nsteps = reader.GetNumberOfTimeSteps()
    times = [reader.GetTimeValue(k) for k in range(nsteps)]
    print(f"VTK {vtkVersion.GetVTKVersion()}, CanReadFile {readable}")
    print(f"title: {reader.GetTitle()!r}")
    print(f"nodes: {nodes}   solid cells: {solids}   shells: {reader.GetNumberOfShellCells()}   "
          f"beams: {reader.GetNumberOfBeamCells()}")
    print(f"time steps: {nsteps}   times: {times}")
    print("point arrays:", [reader.GetPointArrayName(k) for k in range(reader.GetNumberOfPointArrays())])
    for kind, label in enumerate(CELL_KINDS):
        n = reader.GetNumberOfCellArrays(kind)
        if n:
            print(f"{label} cell arrays:", [reader.GetCellArrayName(kind, k) for k in range(n)])
    print("parts:", [reader.GetPartArrayName(k) for k in range(reader.GetNumberOfPartArrays())])

    target = tuple(float(v) for v in args.node_xyz.split(",")) if args.node_xyz else None
    record = {"vtk": vtkVersion.GetVTKVersion(), "title": reader.GetTitle(), "nodes": nodes,
              "solids": solids, "times": times, "steps": []}
    chosen = []
    for step in range(nsteps):
        reader.SetTimeStep(step)
        reader.Update()
        parts = []
        for name, grid in part_blocks(reader.GetOutput()):
            initial = vtk_to_numpy(grid.GetPoints().GetData()).astype(float)
            pdata, cdata = grid.GetPointData(), grid.GetCellData()
            current = as_array(pdata, "Deflected Coordinates")
            position = initial if current is None else current.astype(float)
            velocity = as_array(pdata, "Velocity")
            temperature = as_array(pdata, "Temperature")
            user_ids = as_array(pdata, "UserID")
            entry = {"name": name, "npoints": grid.GetNumberOfPoints(), "ncells": grid.GetNumberOfCells(),
                     "initial": initial.tolist(), "position": position.tolist(),
                     "point_arrays": [pdata.GetArrayName(k) for k in range(pdata.GetNumberOfArrays())],
                     "cell_arrays": {cdata.GetArrayName(k): vtk_to_numpy(cdata.GetArray(k)).tolist()
                                     for k in range(cdata.GetNumberOfArrays())}}
            if velocity is not None:
                entry["velocity"] = velocity.tolist()
            if temperature is not None:
                entry["temperature"] = temperature.tolist()
            if user_ids is not None:
                entry["UserID"] = user_ids.tolist()
            parts.append(entry)
            print(f"  step {step} t={times[step]:.6g} part '{name}': {grid.GetNumberOfPoints()} points, "
                  f"{grid.GetNumberOfCells()} cells")
            scale = 1e-6 * (1 + (math.dist(target, (0, 0, 0)) if target else 0))
            for q in range(grid.GetNumberOfPoints()):
                if args.all or (target is not None and math.dist(initial[q], target) < scale):
                    chosen.append(f"  {step} {times[step]:.6g} {name} {q} "
                                  f"{None if user_ids is None else int(user_ids[q])} {triple(initial[q])} -> "
                                  f"{triple(position[q])} | {triple(position[q] - initial[q])} | "
                                  f"{triple(None if velocity is None else velocity[q])} | "
                                  f"{None if temperature is None else float(temperature[q])}")
            if not args.quiet_cells:
                for c in range(grid.GetNumberOfCells()):
                    values = {cdata.GetArrayName(k): vtk_to_numpy(cdata.GetArray(k))[c].tolist()
                              for k in range(cdata.GetNumberOfArrays())}
                    print(f"  step {step} t={times[step]:.6g} part '{name}' cell {c} "
                          f"type={grid.GetCellType(c)} npts={grid.GetCell(c).GetNumberOfPoints()} {values}")
        record["steps"].append({"step": step, "time": times[step], "parts": parts})

    if chosen:
        print("selected node(s): step time part index user_id initial -> position | displacement | velocity | T")
        print("\n".join(chosen))
    elif target is not None:
        print("selected node not found (wrong coordinates?)")

    vtk_text = messages.GetOutput()
    if vtk_text.strip():
        print("VTK messages:\n" + vtk_text)
    if args.json:
        with open(args.json, "w") as out:
            json.dump(record, out, indent=1)
        print(f"wrote {args.json}")

    failed = "ERROR" in vtk_text or nodes == 0 or nsteps == 0
    for wanted, found, what in ((args.expect_nodes, nodes, "nodes"), (args.expect_solids, solids, "solid cells"),
                                (args.expect_shells, reader.GetNumberOfShellCells(), "shell cells"),
                                (args.expect_beams, reader.GetNumberOfBeamCells(), "beam cells"),
                                (args.expect_steps, nsteps, "time steps")):
        if wanted is not None and wanted != found:
            print(f"MISMATCH: expected {wanted} {what}, VTK found {found}")
            failed = True
    print("RESULT:", "FAIL" if failed else "OK")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())

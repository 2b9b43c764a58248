#!/usr/bin/python3
# Copyright (c) 2026 Delaunay_from_prediction contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# A real mesher's output as a prediction: a 2 x 1 plate with four circular holes, meshed by
# gmsh's Frontal-Delaunay 2D algorithm (Mesh.Algorithm = 6) at about NODES nodes, written as
# Triangle files POINTS.node and FACES.ele (numbered from 0, in gmsh's node and element
# order). Needs Debian's python3-gmsh (apt-get install python3-gmsh).
#
#   scripts/make_gmsh_plate.py NODES POINTS.node FACES.ele
#   e.g. scripts/make_gmsh_plate.py 2e5 plate_2e5.node plate_2e5.ele
import math
import sys

import gmsh

if len(sys.argv) != 4:
    sys.exit("usage: make_gmsh_plate.py NODES POINTS.node FACES.ele")
target, node_file, ele_file = int(float(sys.argv[1])), sys.argv[2], sys.argv[3]

gmsh.initialize()
gmsh.option.setNumber("General.Terminal", 0)
occ = gmsh.model.occ
plate = occ.addRectangle(0, 0, 0, 2, 1)
holes = [occ.addDisk(x, y, 0, r, r) for x, y, r in
         [(0.4, 0.3, 0.12), (0.7, 0.7, 0.15), (1.3, 0.35, 0.1), (1.6, 0.65, 0.18)]]
occ.cut([(2, plate)], [(2, h) for h in holes])
occ.synchronize()
area = 2 - math.pi * (0.12**2 + 0.15**2 + 0.1**2 + 0.18**2)
# Edge length h of equilateral triangles: 2 / (sqrt(3) h^2) nodes per unit area.
h = math.sqrt(2 * area / (math.sqrt(3) * target))
gmsh.option.setNumber("Mesh.Algorithm", 6)  # Frontal-Delaunay
gmsh.option.setNumber("Mesh.MeshSizeMin", h)
gmsh.option.setNumber("Mesh.MeshSizeMax", h)
gmsh.model.mesh.generate(2)

tags, coords, _ = gmsh.model.mesh.getNodes()
index = {int(t): i for i, t in enumerate(tags)}
_, element_tags, element_nodes = gmsh.model.mesh.getElements(2)
triangles = element_nodes[0]  # type 2: 3-node triangles (the only 2D type generated)
gmsh.finalize()

with open(node_file, "w") as out:
    out.write(f"{len(tags)} 2 0 0\n")
    out.writelines(f"{i} {coords[3 * i]!r} {coords[3 * i + 1]!r}\n" for i in range(len(tags)))
m = len(triangles) // 3
with open(ele_file, "w") as out:
    out.write(f"{m} 3 0\n")
    out.writelines(f"{k} {index[int(triangles[3 * k])]} {index[int(triangles[3 * k + 1])]} "
                   f"{index[int(triangles[3 * k + 2])]}\n" for k in range(m))
print(f"{node_file}: {len(tags)} nodes; {ele_file}: {m} triangles (h = {h:.6g})")

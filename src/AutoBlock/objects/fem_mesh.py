"""FEM mesh objects (Fem::FemMeshObject) from quads, so that FreeCAD's FEM workbench can use AutoBlock's
meshes. The core's quad mesher (the meshing issue) gives nodes and quads; this turns them into a
document object."""

import FreeCAD


def fem_mesh(nodes, quads):
    """A Fem.FemMesh of 4-node quads. nodes: [(x, y, z)]; quads: [(a, b, c, d)] of 0-based node indices,
    counter-clockwise. Raises ValueError for a bad index or a degenerate quad."""
    import Fem

    count = len(nodes)
    mesh = Fem.FemMesh()
    for number, (x, y, z) in enumerate(nodes, 1):
        mesh.addNode(float(x), float(y), float(z), number)
    for number, quad in enumerate(quads, 1):
        quad = [int(i) for i in quad]
        if len(quad) != 4:
            raise ValueError("quad {} has {} nodes, expected 4".format(number, len(quad)))
        if len(set(quad)) != 4:
            raise ValueError("quad {} repeats a node: {}".format(number, quad))
        if min(quad) < 0 or max(quad) >= count:
            raise ValueError("quad {} refers to a node outside 0..{}: {}".format(number, count - 1, quad))
        mesh.addFace([i + 1 for i in quad], number)
    return mesh


def make_fem_mesh_object(doc, nodes, quads, name="AutoBlockMesh", label=None):
    """Add a Fem::FemMeshObject holding the quads to `doc` and return it."""
    mesh = fem_mesh(nodes, quads)
    obj = doc.addObject("Fem::FemMeshObject", name)
    obj.FemMesh = mesh
    if label:
        obj.Label = label
    if FreeCAD.GuiUp:
        try:
            obj.ViewObject.DisplayMode = "Faces & Wireframe"
        except Exception:
            pass
    return obj

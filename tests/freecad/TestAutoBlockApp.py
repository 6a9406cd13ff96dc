"""App tests of the AutoBlock workbench, headless: freecadcmd -t TestAutoBlockApp (see run_freecad_tests.sh).

Console API, the parametric object (recompute when the source changes, undo, save and reopen),
write-back, bad faces, stepping with value scores, quad meshes and FEM mesh objects, mesh files, the
training protocol and a real (tiny) training run.
"""

import json
import math
import os
import subprocess
import threading
import time
import unittest

import FreeCAD
import Part

import AutoBlock
import autoblock_test_support as support


class TestNativeModule(unittest.TestCase):
    def test_loading_the_package_does_not_load_the_native_module(self):
        code = ("import sys; sys.path += {!r}; import FreeCAD, AutoBlock, AutoBlock.paths, AutoBlock.commands; "
                "print('native' if 'autoblock_native' in sys.modules else 'lazy')").format(
                    ["/usr/lib/freecad-python3/lib", os.path.dirname(os.path.dirname(AutoBlock.__file__))])
        out = subprocess.run(["/usr/bin/python3", "-c", code], capture_output=True, text=True, timeout=120)
        self.assertEqual(out.stdout.strip().splitlines()[-1], "lazy", out.stderr)

    def test_a_missing_native_module_is_explained(self):
        code = ("import sys; sys.path += {!r}; import FreeCAD, Part, AutoBlock, AutoBlock.paths as p; "
                "p.native_dirs = lambda: ['/nonexistent'];\n"
                "try:\n    AutoBlock.decompose(Part.makePlane(1, 1))\n"
                "except RuntimeError as e:\n    print(type(e).__name__, e)").format(
                    ["/usr/lib/freecad-python3/lib", os.path.dirname(os.path.dirname(AutoBlock.__file__))])
        env = dict(os.environ)
        env.pop("AUTOBLOCK_NATIVE_DIR", None)
        out = subprocess.run(["/usr/bin/python3", "-c", code], capture_output=True, text=True, timeout=120, env=env)
        self.assertIn("NativeModuleMissing", out.stdout, out.stderr)
        self.assertIn("./setup.sh build", out.stdout)

    def test_catalogue_comes_from_the_core(self):
        from AutoBlock import native

        module = native.load()
        self.assertEqual(AutoBlock.policy_names(), list(module.policy_names()))
        self.assertEqual(AutoBlock.policy_names(), ["auto", "sac-faithful", "sac-mesh", "sac-paper", "optimal",
                                                    "greedy", "random-split", "random"])
        self.assertEqual(module.default_policy(), "auto")
        self.assertEqual(AutoBlock.default_policy(), "auto")  # no preference set in the test's user folder
        self.assertEqual(AutoBlock.reward_presets(), ["paper", "mesh"])
        self.assertEqual(module.default_reward_preset(), "")
        self.assertEqual(AutoBlock.capabilities(), {"learned_policies": True, "training": True, "vertex_scores": True,
                                                    "meshing": True})
        self.assertEqual(AutoBlock.policy_info(), {"name": "auto", "learned": False, "reward": "mesh",
                                                   "scores_by": "sac-mesh", "general_network": False})
        self.assertEqual(AutoBlock.policy_info("sac-mesh"), {"name": "sac-mesh", "learned": True, "reward": "mesh",
                                                             "scores_by": "sac-mesh", "general_network": False})
        self.assertEqual(AutoBlock.policy_info("sac-paper")["reward"], "paper")
        self.assertEqual(AutoBlock.policy_info("greedy"), {"name": "greedy", "learned": False, "reward": "paper",
                                                           "scores_by": None, "general_network": False})

    def test_input_errors_are_value_errors(self):
        from AutoBlock import native

        module = native.load()
        with self.assertRaisesRegex(ValueError, "not readable BREP"):
            module.check_face("garbage")
        brep = support.read_face().exportBrepToString()
        with self.assertRaisesRegex(ValueError, "unknown policy 'nope'"):
            module.decompose(brep, policy="nope")
        with self.assertRaisesRegex(ValueError, "unknown reward preset"):
            module.decompose(brep, reward="nope")
        with self.assertRaisesRegex(ValueError, "does not belong to this face"):
            module.step(brep, [(0, 0.5, 0.25, "vertical")], 1)
        cuts = [(c["part"], c["vertex"][0], c["vertex"][1], c["direction"])
                for c in module.decompose(brep, policy="optimal")["cuts"]]
        with self.assertRaisesRegex(ValueError, "baseline: it has no value network"):
            module.vertex_scores(brep, cuts, 0, "optimal")
        with self.assertRaisesRegex(ValueError, "unknown policy '/no/such.pt'"):
            module.vertex_scores(brep, cuts, 0, "/no/such.pt")
        with self.assertRaisesRegex(ValueError, "expected a .msh, .vtu or .inp file"):
            module.mesh(brep, cuts, 0.5, out="/tmp/mesh.stl")
        with self.assertRaisesRegex(ValueError, "12 numbers"):
            module.mesh(brep, cuts, 0.5, out="/tmp/mesh.msh", placement=[1.0, 2.0])
        with self.assertRaisesRegex(ValueError, "ends after"):
            module.mesh(brep, cuts[:-1], 0.5)
        # A general sequence's stored rules and minimum intervals are checked where they are read.
        with self.assertRaisesRegex(ValueError, "block rules are 3 numbers"):
            module.mesh(brep, cuts, 0.5, rules=[50.0, 130.0])
        with self.assertRaisesRegex(ValueError, "0 < min corner < max corner"):
            module.step(brep, cuts, 0, rules=[130.0, 50.0, 20.0])
        with self.assertRaisesRegex(ValueError, "min_edge_intervals: expected 1 to 1000"):
            module.mesh(brep, cuts, 0.5, min_edge_intervals=0)
        with self.assertRaisesRegex(ValueError, "min_edge_intervals: expected 1 to 1000"):
            module.replay(brep, cuts, min_edge_intervals=0)
        with self.assertRaisesRegex(ValueError, "does not exist"):
            module.train({"output": "/no/such/folder/p.pt", "train_folder": support.SAMPLES,
                          "test_folder": support.SAMPLES})


class TestText(unittest.TestCase):
    def test_counts_agree_with_their_nouns(self):
        from AutoBlock import text

        self.assertEqual(text.counted(0, "cut"), "0 cuts")
        self.assertEqual(text.counted(1, "cut"), "1 cut")
        self.assertEqual(text.counted(2, "cut"), "2 cuts")
        self.assertEqual(text.counted(1, "vertex", "vertices"), "1 vertex")
        self.assertEqual(text.counted(4, "vertex", "vertices"), "4 vertices")

    def test_numbers_read_as_a_cad_user_writes_them_the_cores_way(self):
        from AutoBlock import text

        self.assertEqual(text.number(80), "80")
        self.assertEqual(text.number(0.1), "0.1")
        self.assertEqual(text.number(-2.22044604925031e-15, 1e-5), "0")
        self.assertEqual(text.number(82.99999999999999, 1e-5), "83")
        self.assertEqual(text.number(1e20), "1e20")
        self.assertEqual(text.number(2.5e-9), "2.5e-9")
        self.assertEqual(text.vector(FreeCAD.Vector(80, 3.0000000000000004, -1e-16), text.tolerance_of(83)), "(80, 3, 0)")
        self.assertEqual(text.point(0.5, 12), "(0.5, 12)")
        self.assertEqual(text.significant(12345.6), "12350")
        self.assertEqual(text.significant(0.61234, 3), "0.612")

    def test_messages_about_faces_print_coordinates_plainly(self):
        # A corner of 1.8 degrees, with the noise OpenCASCADE's operations leave in coordinates: the core's
        # message, through the binding, prints plain numbers.
        face = Part.makePolygon([FreeCAD.Vector(0, 0, 0), FreeCAD.Vector(80, -2.22044604925031e-15, 0),
                                 FreeCAD.Vector(0, 2.5000000000000004, 0), FreeCAD.Vector(0, 0, 0)])
        with self.assertRaises(ValueError) as caught:
            AutoBlock.decompose(Part.Face(face))
        message = str(caught.exception)
        self.assertIn("degrees at (80, 0)", message)
        self.assertNotIn("e+", message)
        self.assertNotIn("e-", message)

    def test_a_too_sharp_corner_is_named_with_its_place(self):
        # Faces with edges at other angles go to the general engine; a corner sharper than it takes is named.
        V = FreeCAD.Vector
        sliver = Part.Face(Part.makePolygon([V(0, 0, 0), V(40, 0, 0), V(0, 2, 0), V(0, 0, 0)]))
        with self.assertRaises(ValueError) as caught:
            AutoBlock.decompose(sliver)
        self.assertIn("sharper than the smallest supported 5 degrees", str(caught.exception))
        self.assertIn("at (40, 0)", str(caught.exception))


class TestDecompose(unittest.TestCase):
    def check_partition(self, result, face):
        self.assertEqual(len(result.blocks), result.n_blocks)
        self.assertEqual(len(result.shape.Faces), result.n_blocks)
        self.assertAlmostEqual(sum(b.Area for b in result.blocks), face.Area, places=6)
        for block in result.blocks:
            self.assertIsInstance(block, Part.Face)
            self.assertTrue(support.is_rectangle(block), block.BoundBox)
            self.assertTrue(block.isValid())
        self.assertAlmostEqual(result.ret, sum(c.reward for c in result.cuts), places=9)
        self.assertGreaterEqual(result.n_blocks, result.min_blocks)

    def test_decompose_a_sample_face(self):
        face = support.read_face()
        result = AutoBlock.decompose(face)
        self.assertEqual(result.policy, "auto")
        self.assertEqual(result.reward, "mesh")  # the policy's own preset
        self.assertTrue(result.complete)
        self.check_partition(result, face)
        # The shape is the conformal merge: neighbouring blocks share their edges, so the edges that belong to one
        # face only are exactly the face's boundary.
        faces_of = [len(result.shape.ancestorsOfType(e, Part.Face)) for e in result.shape.Edges]
        self.assertEqual(set(faces_of), {1, 2})
        boundary = sum(e.Length for e, n in zip(result.shape.Edges, faces_of) if n == 1)
        self.assertAlmostEqual(boundary, sum(w.Length for w in face.Wires), places=9)
        self.assertEqual(AutoBlock.decompose(face, reward="paper").reward, "paper")
        self.assertEqual(AutoBlock.decompose(face, reward="").reward, "mesh")
        self.assertEqual(AutoBlock.decompose(face, policy="optimal").reward, "paper")
        self.assertEqual(result.cuts[0].direction in ("horizontal", "vertical"), True)
        self.assertIsInstance(result.cuts[0].vertex, FreeCAD.Vector)
        self.assertIn("blocks (minimum", result.summary())
        json.dumps(result.to_dict())

    def test_same_result_as_the_cli(self):
        cli = os.environ.get("AUTOBLOCK_CLI")
        if not cli:
            self.skipTest("AUTOBLOCK_CLI not set")
        folder = support.temporary_folder()
        try:
            report = os.path.join(folder, "report.json")
            subprocess.run([cli, "decompose", support.SAMPLE, "--json", report], check=True, capture_output=True)
            with open(report) as f:
                expected = json.load(f)
        finally:
            support.remove_folder(folder)
        result = AutoBlock.decompose(support.read_face())
        self.assertEqual(result.n_blocks, expected["n_blocks"])
        self.assertAlmostEqual(result.ret, expected["return"], places=9)
        self.assertEqual([c.local for c in result.cuts], [tuple(c["vertex"]) for c in expected["cuts"]])

    def test_the_cli_numbers_a_steps_faces_as_freecad_does(self):
        """`autoblock faces` and `--face N` on a solid FreeCAD wrote to STEP: FaceN is the same face on both sides."""
        cli = os.environ.get("AUTOBLOCK_CLI")
        if not cli:
            self.skipTest("AUTOBLOCK_CLI not set")
        folder = support.temporary_folder()
        try:
            solid = support.l_face(width=6, height=5, notch=3).extrude(FreeCAD.Vector(0, 0, 2))
            path = os.path.join(folder, "part.step")
            solid.exportStep(path)
            shape = Part.read(path)
            listed = subprocess.run([cli, "faces", path], capture_output=True, text=True, timeout=60)
            self.assertEqual(listed.returncode, 0, listed.stderr)
            rows = [line.split() for line in listed.stdout.splitlines()[2:]]
            self.assertEqual(len(rows), len(shape.Faces))
            for row, face in zip(rows, shape.Faces):
                self.assertAlmostEqual(float(row[2]), face.Area, places=4)
            top = [i for i, f in enumerate(shape.Faces, 1) if f.BoundBox.ZLength < 1e-9 and f.BoundBox.ZMin > 1]
            self.assertEqual(len(top), 1)
            self.assertEqual(rows[top[0] - 1][3:6], ["(0,", "0,", "1)"])
            report = os.path.join(folder, "report.json")
            run = subprocess.run([cli, "decompose", path, "--face", str(top[0]), "--json", report], capture_output=True,
                                 text=True, timeout=120)
            self.assertEqual(run.returncode, 0, run.stderr)
            self.assertTrue(run.stdout.startswith("{} (Face{}): ".format(path, top[0])))
            with open(report) as f:
                expected = json.load(f)
            result = AutoBlock.decompose(shape.Faces[top[0] - 1])
            self.assertEqual(result.n_blocks, expected["n_blocks"])
            self.assertAlmostEqual(expected["face"]["z"], 2.0)
            # Without --face, a swept solid has its cap decomposed (issue 11); two solids need --face N.
            whole = subprocess.run([cli, "decompose", path], capture_output=True, text=True, timeout=60)
            self.assertEqual(whole.returncode, 0, whole.stderr)
            self.assertIn("solid, caps Face", whole.stdout)
            two = os.path.join(folder, "two.step")
            Part.makeCompound([solid, solid.translated(FreeCAD.Vector(10, 0, 0))]).exportStep(two)
            missing = subprocess.run([cli, "decompose", two], capture_output=True, text=True, timeout=60)
            self.assertEqual(missing.returncode, 2)
            self.assertIn("--face N", missing.stderr)
            self.assertIn("autoblock faces", missing.stderr)
        finally:
            support.remove_folder(folder)

    def test_every_policy_and_holes(self):
        face = support.read_face(support.HOLES_SAMPLE)
        self.assertGreater(len(face.Wires), 1)
        for policy in AutoBlock.policy_names():
            with self.subTest(policy=policy):
                result = AutoBlock.decompose(face, policy=policy, seed=3)
                self.assertEqual(result.policy, policy)
                self.assertTrue(result.complete)
                self.check_partition(result, face)

    def test_a_sketch_on_the_xz_plane(self):
        doc = support.new_document("xz")
        try:
            placement = FreeCAD.Placement(FreeCAD.Vector(0, 5, 0), FreeCAD.Rotation(FreeCAD.Vector(1, 0, 0), 90))
            sketch = support.add_l_sketch(doc, placement)
            result = AutoBlock.decompose(sketch)
            self.assertEqual(result.n_blocks, 2)
            self.assertAlmostEqual(sum(b.Area for b in result.blocks), 12.0, places=9)
            box = result.shape.BoundBox
            self.assertAlmostEqual(box.YMin, 5.0, places=9)
            self.assertAlmostEqual(box.YMax, 5.0, places=9)
            self.assertAlmostEqual(box.ZLength, 4.0, places=9)
            for cut in result.cuts:
                self.assertAlmostEqual(cut.vertex.y, 5.0, places=9)
        finally:
            support.close_document(doc)

    def test_a_face_turned_within_its_plane(self):
        face = support.l_face(width=6, height=5, notch=3)
        face.rotate(FreeCAD.Vector(1, 2, 0), FreeCAD.Vector(0, 0, 1), 30)
        result = AutoBlock.decompose(face)
        self.check_partition(result, face)
        self.assertEqual(result.n_blocks, 2)
        # The blocks lie where the face does.
        self.assertAlmostEqual(face.common(result.shape).Area, face.Area, places=6)

    def test_a_face_of_an_object(self):
        doc = support.new_document("sub")
        try:
            box = doc.addObject("Part::Box", "Box")
            box.Placement.Base = FreeCAD.Vector(10, 0, 0)
            doc.recompute()
            result = AutoBlock.decompose((box, "Face6"))
            self.assertEqual(result.n_blocks, 1)
            self.assertAlmostEqual(result.shape.BoundBox.XMin, 10.0)
            self.assertAlmostEqual(result.shape.BoundBox.ZMin, 10.0)
        finally:
            support.close_document(doc)

    def test_faces_inside_containers_keep_their_placement(self):
        doc = support.new_document("body")
        try:
            body = doc.addObject("PartDesign::Body", "Body")
            sketch = support.add_l_sketch(doc)
            body.addObject(sketch)
            pad = doc.addObject("PartDesign::Pad", "Pad")
            body.addObject(pad)
            pad.Profile = sketch
            pad.Length = 3
            body.Placement.Base = FreeCAD.Vector(100, 0, 0)
            doc.recompute()
            top = [i for i, f in enumerate(pad.Shape.Faces, 1) if abs(f.BoundBox.ZMin - 3) < 1e-9
                   and f.BoundBox.ZLength < 1e-9][0]
            obj = AutoBlock.make_autoblock(body, "Pad.Face{}".format(top))
            self.assertAlmostEqual(obj.Shape.BoundBox.XMin, 100.0)
            self.assertAlmostEqual(obj.Shape.BoundBox.ZMin, 3.0)
            pad.Length = 5
            doc.recompute()
            self.assertAlmostEqual(obj.Shape.BoundBox.ZMin, 5.0)
            result = AutoBlock.decompose((body, "Sketch."))
            self.assertAlmostEqual(result.shape.BoundBox.XMin, 100.0)
            self.assertEqual(result.n_blocks, 2)
        finally:
            support.close_document(doc)

    def test_selections_map_to_targets(self):
        from AutoBlock.faces import selection_target

        doc = support.new_document("selection")
        try:
            body = doc.addObject("PartDesign::Body", "Body")
            sketch = support.add_l_sketch(doc)
            body.addObject(sketch)
            doc.recompute()
            self.assertEqual(selection_target(body, "Sketch.Edge3")[1:], ("Sketch.", sketch))
            self.assertEqual(selection_target(body, "Sketch.")[1:], ("Sketch.", sketch))
            self.assertEqual(selection_target(sketch, "Edge3")[1:], (None, sketch))
            self.assertEqual(selection_target(sketch, "")[1:], (None, sketch))
            self.assertEqual(selection_target(body, "Pad.Face2")[1], "Pad.Face2")
        finally:
            support.close_document(doc)

    def test_bad_faces_raise_value_error(self):
        doc = support.new_document("bad")
        try:
            sphere = doc.addObject("Part::Sphere", "Sphere")
            box = doc.addObject("Part::Box", "Box")
            doc.recompute()
            V = FreeCAD.Vector
            sliver = Part.Face(Part.makePolygon([V(0, 0, 0), V(40, 0, 0), V(0, 2, 0), V(0, 0, 0)]))
            oval = Part.Face(Part.Wire(Part.Ellipse(V(0, 0, 0), 3.0, 1.0).toShape()))  # circles are accepted
            cases = [
                (sphere, "not planar"),
                (box, "6 faces"),
                ((box, "Edge1"), "not a face"),
                (sliver, "sharper than the smallest supported"),
                (oval, "only straight edges and circular arcs"),
                (Part.makeCompound([support.l_face(), support.l_face().translate(V(10, 0, 0))]), "2 faces"),
                (Part.makePolygon([V(0, 0, 0), V(1, 0, 0), V(1, 1, 0)]), "its wire is not closed"),
            ]
            for target, words in cases:
                with self.subTest(words=words):
                    with self.assertRaisesRegex(ValueError, words):
                        AutoBlock.decompose(target)
            with self.assertRaises(TypeError):
                AutoBlock.decompose(42)
            with self.assertRaisesRegex(ValueError, "unknown policy"):
                AutoBlock.decompose(support.l_face(), policy="nope")
            if not AutoBlock.capabilities()["learned_policies"]:
                with self.assertRaisesRegex(ValueError, "no learned policies"):
                    AutoBlock.decompose(support.l_face(), policy="/tmp/my-policy.pt")
        finally:
            support.close_document(doc)

    def test_stepping_through_a_result(self):
        face = support.read_face()
        result = AutoBlock.decompose(face)
        self.assertEqual(result.policy, "auto")
        stepper = result.stepper()
        self.assertEqual(stepper.reward, "mesh")
        self.assertEqual(stepper.steps, len(result.cuts))
        running = 0.0
        for k in range(stepper.steps + 1):
            view = stepper.step(k)
            self.assertAlmostEqual(sum(p.face.Area for p in view.pieces), face.Area, places=6)
            self.assertAlmostEqual(view.ret, running, places=9)
            if k < stepper.steps:
                cut = result.cuts[k]
                self.assertEqual(view.next.part, cut.part)
                self.assertTrue(view.next.vertex.isEqual(cut.vertex, 1e-9))
                self.assertIn(view.next.vertex, view.next.vertices)
                self.assertAlmostEqual(view.next.reward, cut.reward, places=9)
                self.assertGreater(len(view.next.line), 0)
                # The value network's score at every vertex of the part (None where no cut through it counts);
                # the deployed policy cuts at a best one.
                scores = view.next.scores
                self.assertEqual(len(scores), len(view.next.vertices))
                known = [x for x in scores if x is not None]
                self.assertGreater(len(known), 1)
                self.assertAlmostEqual(scores[view.next.chosen], max(known), places=4)
                self.assertEqual(view.next.scores_note, "")
                running += cut.reward
            else:
                self.assertIsNone(view.next)
                self.assertEqual(view.blocks, result.n_blocks)
                self.assertEqual(sorted(p.index for p in view.pieces), list(range(result.n_blocks)))
        # A baseline has no value network: no scores, and a note that says why.
        first = AutoBlock.decompose(face, policy="optimal").stepper().step(0).next
        self.assertIsNone(first.scores)
        self.assertIn("'optimal' is a baseline", first.scores_note)


class TestBatchExample(unittest.TestCase):
    SCRIPT = os.path.join(os.path.dirname(AutoBlock.__file__), "examples", "batch_decompose.py")

    def test_the_readme_shows_the_script_as_it_is(self):
        readme = os.path.join(AutoBlock.paths.ROOT, "README.md")
        with open(readme) as f:
            text = f.read()
        with open(self.SCRIPT) as f:
            script = f.read()
        self.assertIn("```python\n" + script + "```", text)

    def test_the_batch_script_decomposes_a_folder(self):
        folder = support.temporary_folder()
        try:
            inputs = os.path.join(folder, "in")
            os.makedirs(inputs)
            names = ["shape_0000.brep", "shape_0001.brep"]
            for name in names:
                Part.read(os.path.join(support.SAMPLES, name)).exportBrep(os.path.join(inputs, name))
            Part.makeSphere(1.0).exportStep(os.path.join(inputs, "sphere.step"))
            out = os.path.join(folder, "out")
            run = subprocess.run(["freecadcmd", self.SCRIPT, inputs, out], capture_output=True, text=True,
                                 timeout=120)
            self.assertEqual(run.returncode, 1, run.stdout + run.stderr)  # one file skipped
            lines = [line for line in run.stdout.splitlines() if line.startswith("[")]
            self.assertEqual(len(lines), 3)
            self.assertTrue(lines[0].startswith("[1/3] shape_0000.brep: "), lines)
            self.assertIn("blocks (minimum", lines[0])
            self.assertIn("quads, size", lines[0])
            self.assertIn("sphere.step: skipped: ", lines[2])
            with open(os.path.join(out, "summary.json")) as f:
                summary = json.load(f)
            self.assertEqual([entry["file"] for entry in summary], names)
            for entry in summary:
                blocks = Part.read(os.path.join(out, entry["file"].replace(".brep", "-blocks.brep")))
                self.assertEqual(len(blocks.Faces), entry["n_blocks"])
                with open(os.path.join(out, entry["mesh"])) as f:
                    text = f.read()
                self.assertTrue(text.startswith("$MeshFormat\n4.1 0 8\n"))
                self.assertIn("\n{} {} 1 {}\n".format(entry["n_blocks"], entry["quads"], entry["quads"]), text)
        finally:
            support.remove_folder(folder)


class TestAutoBlockObject(unittest.TestCase):
    def setUp(self):
        self.doc = support.new_document("objects")
        self.folder = support.temporary_folder()

    def tearDown(self):
        support.close_document(self.doc)
        support.remove_folder(self.folder)

    def test_make_autoblock(self):
        source = support.add_face(self.doc, support.read_face())
        obj = AutoBlock.make_autoblock(source)
        self.assertTrue(AutoBlock.is_autoblock(obj))
        self.assertEqual(obj.Source[0], source)
        self.assertEqual(obj.Policy, "auto")
        self.assertEqual(obj.RewardPreset, "")  # the policy's own ...
        self.assertEqual(obj.RewardUsed, "mesh")  # ... which is auto's mesh preset
        self.assertEqual(obj.getEnumerationsOfProperty("Policy"), AutoBlock.policy_names())
        self.assertEqual(obj.getEnumerationsOfProperty("RewardPreset"), ["", "paper", "mesh"])
        expected = AutoBlock.decompose(source)
        self.assertEqual(obj.NumberOfBlocks, expected.n_blocks)
        self.assertEqual(len(obj.Shape.Faces), expected.n_blocks)
        self.assertAlmostEqual(obj.Return, expected.ret, places=9)
        self.assertEqual(obj.NumberOfCuts, len(expected.cuts))
        self.assertIn("blocks (minimum", obj.Status)
        self.assertIn("Up-to-date", obj.State)
        self.assertAlmostEqual(obj.Shape.Area, source.Shape.Area, places=6)

    def test_recompute_after_the_source_changes(self):
        source = support.add_face(self.doc, support.l_face())
        obj = AutoBlock.make_autoblock(source)
        self.assertEqual(obj.NumberOfBlocks, 2)
        source.Shape = support.read_face()
        with self.assertRaisesRegex(ValueError, "out of date"):
            AutoBlock.stepper_of(obj)
        self.doc.recompute()
        self.assertEqual(obj.NumberOfBlocks, AutoBlock.decompose(source).n_blocks)
        self.assertAlmostEqual(obj.Shape.Area, source.Shape.Area, places=6)
        # A parametric source: the top face of a box, resized.
        box = self.doc.addObject("Part::Box", "Box")
        self.doc.recompute()
        top = AutoBlock.make_autoblock(box, "Face6")
        self.assertAlmostEqual(top.Shape.Area, 100.0)
        box.Length = 25
        self.doc.recompute()
        self.assertAlmostEqual(top.Shape.Area, 250.0)
        # A sketch: moving its placement moves the blocks.
        sketch = support.add_l_sketch(self.doc)
        blocks = AutoBlock.make_autoblock(sketch)
        sketch.Placement.Base = FreeCAD.Vector(0, 0, 7)
        self.doc.recompute()
        self.assertAlmostEqual(blocks.Shape.BoundBox.ZMin, 7.0)
        # A source that becomes unsupported: the object reports the error, FreeCAD carries on.
        source.Shape = Part.makeSphere(1.0)
        self.doc.recompute()
        self.assertIn("Invalid", obj.State)
        self.assertIsInstance(obj.Proxy.last_error, ValueError)
        source.Shape = support.l_face()
        self.doc.recompute()
        self.assertIn("Up-to-date", obj.State)
        self.assertEqual(obj.NumberOfBlocks, 2)

    def test_changing_the_policy_recomputes(self):
        source = support.add_face(self.doc, support.read_face(support.HOLES_SAMPLE))
        obj = AutoBlock.make_autoblock(source, policy="optimal")
        self.assertEqual(obj.RewardUsed, "paper")
        optimal = obj.Return
        obj.Policy = "random"
        obj.Seed = 5
        self.doc.recompute()
        self.assertEqual(obj.Status.split(":")[0], "random")
        self.assertLessEqual(obj.Return, optimal + 1e-9)
        # The optimal search maximises the preset it is given.
        obj.Policy = "optimal"
        obj.RewardPreset = "mesh"
        self.doc.recompute()
        self.assertEqual(obj.RewardUsed, "mesh")
        self.assertAlmostEqual(obj.Return, AutoBlock.decompose(source, policy="optimal", reward="mesh").ret, places=9)

    def test_undo_and_redo(self):
        source = support.add_face(self.doc, support.read_face())
        count = len(self.doc.Objects)
        undo_count = self.doc.UndoCount
        obj = AutoBlock.make_autoblock(source)
        name = obj.Name
        self.assertEqual(self.doc.UndoCount, undo_count + 1)
        self.assertEqual(self.doc.UndoNames[0], "Auto-Block")
        self.doc.undo()
        self.assertIsNone(self.doc.getObject(name))
        self.assertEqual(len(self.doc.Objects), count)
        self.doc.redo()
        obj = self.doc.getObject(name)
        self.assertIsNotNone(obj)
        self.doc.recompute()
        self.assertEqual(len(obj.Shape.Faces), obj.NumberOfBlocks)

    def test_bad_faces_leave_the_document_unchanged(self):
        sphere = self.doc.addObject("Part::Sphere", "Sphere")
        source = support.add_face(self.doc, support.l_face())
        names = [o.Name for o in self.doc.Objects]
        undo_count = self.doc.UndoCount
        with self.assertRaisesRegex(ValueError, "not planar"):
            AutoBlock.make_autoblock(sphere)
        with self.assertRaisesRegex(ValueError, "unknown reward preset"):
            AutoBlock.make_autoblock(source, reward="nope")
        # These fail in the object's recompute, after it was added: it is removed again.
        with self.assertRaisesRegex(ValueError, "unknown policy '/tmp/no-such-policy.pt'"):
            AutoBlock.make_autoblock(source, policy="/tmp/no-such-policy.pt")
        garbage = os.path.join(self.folder, "garbage.pt")
        with open(garbage, "w") as f:
            f.write("not a policy")
        with self.assertRaises(ValueError):
            AutoBlock.make_autoblock(source, policy=garbage)
        self.assertEqual([o.Name for o in self.doc.Objects], names)
        self.assertEqual(self.doc.UndoCount, undo_count)
        self.assertIsNone(FreeCAD.getActiveTransaction())
        # Without undo (freecadcmd's default) as well.
        plain = support.new_document("plain", undo=False)
        try:
            source = support.add_face(plain, support.l_face())
            with self.assertRaises(ValueError):
                AutoBlock.make_autoblock(source, policy="/tmp/no-such-policy.pt")
            self.assertEqual([o.Name for o in plain.Objects], [source.Name])
        finally:
            support.close_document(plain)

    def test_save_and_reopen(self):
        source = support.add_face(self.doc, support.read_face())
        sketch_placement = FreeCAD.Placement(FreeCAD.Vector(0, 0, 0), FreeCAD.Rotation(FreeCAD.Vector(0, 1, 0), 90))
        sketch = support.add_l_sketch(self.doc, sketch_placement)
        obj = AutoBlock.make_autoblock(source, policy="greedy")
        side = AutoBlock.make_autoblock(sketch)
        mesh = AutoBlock.mesh(side)
        blocks, ret, area, quads = obj.NumberOfBlocks, obj.Return, obj.Shape.Area, mesh.NumberOfQuads
        path = os.path.join(self.folder, "autoblock.FCStd")
        self.doc.saveAs(path)
        names = (obj.Name, side.Name, source.Name, sketch.Name, mesh.Name)
        FreeCAD.closeDocument(self.doc.Name)
        self.doc = FreeCAD.openDocument(path)
        obj, side, source, sketch, mesh = (self.doc.getObject(n) for n in names)
        self.assertTrue(AutoBlock.is_autoblock(obj))
        from AutoBlock.objects.fem_mesh import is_autoblock_mesh

        self.assertTrue(is_autoblock_mesh(mesh))
        self.assertIs(mesh.AutoBlock, side)
        self.assertEqual(mesh.FemMesh.QuadrangleCount, quads)
        self.assertEqual(obj.Policy, "greedy")
        self.assertEqual(obj.getEnumerationsOfProperty("Policy"), AutoBlock.policy_names())
        self.assertEqual(obj.NumberOfBlocks, blocks)
        self.assertAlmostEqual(obj.Return, ret, places=9)
        self.assertAlmostEqual(obj.Shape.Area, area, places=6)
        self.assertEqual(obj.Source[0], source)
        # Still parametric and steppable after reopening.
        stepper = AutoBlock.stepper_of(obj)
        self.assertEqual(stepper.step(stepper.steps).blocks, blocks)
        source.Shape = support.l_face()
        sketch.Placement.Base = FreeCAD.Vector(3, 0, 0)
        self.doc.recompute()
        self.assertEqual(obj.NumberOfBlocks, 2)
        self.assertAlmostEqual(side.Shape.BoundBox.XMin, 3.0)
        self.assertEqual(AutoBlock.stepper_of(side).step(0).next.n_parts, 2)
        self.assertEqual(AutoBlock.stepper_of(side).reward, "mesh")
        self.assertAlmostEqual(mesh.FemMesh.BoundBox.XMin, 3.0)  # the mesh followed its AutoBlock object
        # And saves again.
        self.doc.save()
        self.assertTrue(os.path.getsize(path) > 0)

    def reported(self):
        """Replaces write_back's report view messages by a list, restored at the end of the test."""
        from AutoBlock.objects import write_back

        said = []
        original = write_back.report
        write_back.report = said.append
        self.addCleanup(setattr, write_back, "report", original)
        return said

    def test_write_back_as_a_new_part_feature(self):
        said = self.reported()
        source = support.add_face(self.doc, support.read_face())
        obj = AutoBlock.make_autoblock(source)
        self.assertTrue(obj.Visibility)
        feature = AutoBlock.write_back(obj, "new")
        name = feature.Name
        self.assertEqual(feature.TypeId, "Part::Feature")
        self.assertEqual(len(feature.Shape.Faces), obj.NumberOfBlocks)
        self.assertAlmostEqual(feature.Shape.Area, obj.Shape.Area)
        self.assertEqual(self.doc.UndoNames[0], "Write back blocks")
        # The AutoBlock object shows the same blocks in the same place: it is hidden, and the report says so.
        self.assertFalse(obj.Visibility)
        self.assertTrue(feature.Visibility)
        self.assertEqual(said, ["wrote the {} blocks of {} to the new Part feature {}; hid {}, which shows the same "
                                "blocks in the same place".format(obj.NumberOfBlocks, obj.Label, feature.Label,
                                                                  obj.Label)])
        self.doc.undo()
        self.assertIsNone(self.doc.getObject(name))
        self.assertTrue(obj.Visibility)
        with self.assertRaisesRegex(ValueError, "'new' or 'replace'"):
            AutoBlock.write_back(obj, "sideways")

    def test_write_back_replacing_the_source(self):
        # A plain face: its shape becomes the blocks; the AutoBlock object has done its job.
        source = support.add_face(self.doc, support.read_face())
        source.Placement.Base = FreeCAD.Vector(0, 0, 3)
        obj = AutoBlock.make_autoblock(source)
        n, name, label = obj.NumberOfBlocks, obj.Name, obj.Label
        said = self.reported()
        result = AutoBlock.write_back(obj, "replace")
        self.assertIs(result, source)
        self.assertTrue(source.Visibility)
        self.assertEqual(len(said), 1)
        self.assertIn("{} now holds the {} blocks in place of its face".format(source.Label, n), said[0])
        self.assertIn("removed {}".format(label), said[0])
        self.assertEqual(len(source.Shape.Faces), n)
        self.assertIsNone(self.doc.getObject(name))
        self.assertEqual(source.Placement.Base, FreeCAD.Vector(0, 0, 3))
        self.assertAlmostEqual(source.Shape.BoundBox.ZMin, 3.0)
        self.doc.undo()
        self.assertEqual(len(source.Shape.Faces), 1)
        self.assertIsNotNone(self.doc.getObject(name))
        # A face of a solid: the solid keeps its other faces and gets the blocks in place of that face.
        solid = support.l_face(width=6, height=5, notch=3).extrude(FreeCAD.Vector(0, 0, 2))
        holder = support.add_face(self.doc, solid, "Solid")
        top = [i for i, f in enumerate(solid.Faces, 1) if abs(f.BoundBox.ZMin - 2) < 1e-9 and f.BoundBox.ZLength < 1e-9]
        obj = AutoBlock.make_autoblock(holder, "Face{}".format(top[0]))
        AutoBlock.write_back(obj, "replace")
        self.assertEqual(len(holder.Shape.Solids), 1)
        self.assertTrue(holder.Shape.isValid())
        self.assertAlmostEqual(holder.Shape.Volume, solid.Volume, places=6)
        self.assertEqual(len(holder.Shape.Faces), len(solid.Faces) + 1)
        # A parametric source cannot be replaced.
        box = self.doc.addObject("Part::Box", "Box")
        self.doc.recompute()
        obj = AutoBlock.make_autoblock(box, "Face6")
        with self.assertRaisesRegex(ValueError, "recomputed from its own inputs"):
            AutoBlock.write_back(obj, "replace")
        self.assertIsNotNone(self.doc.getObject(obj.Name))


def add_rectangle_sketch(body, name, z=0.0):
    """A sketch in body of the 40 x 25 rectangle with a corner at (0, 0, z)."""
    import Sketcher  # noqa: F401

    V = FreeCAD.Vector
    sketch = body.newObject("Sketcher::SketchObject", name)
    sketch.Placement = FreeCAD.Placement(V(0, 0, z), FreeCAD.Rotation())
    corners = [V(0, 0, 0), V(40, 0, 0), V(40, 25, 0), V(0, 25, 0)]
    for a, b in zip(corners, corners[1:] + corners[:1]):
        sketch.addGeometry(Part.LineSegment(a, b))
    return sketch


def add_rectangle_pad(doc):
    """A PartDesign Body with a Pad of a 40 x 25 rectangle (corner at the origin), 5 high: returns (body, pad)."""
    body = doc.addObject("PartDesign::Body", "Body")
    sketch = add_rectangle_sketch(body, "PadSketch")
    pad = body.newObject("PartDesign::Pad", "Pad")
    pad.Profile = sketch
    pad.Length = 5.0
    doc.recompute()
    return body, pad


def add_chamfered_pad(doc):
    """add_rectangle_pad's Pad with one vertical edge chamfered by 8: returns (chamfer, name of its top face,
    the top face)."""
    body, pad = add_rectangle_pad(doc)
    edge = next("Edge{}".format(i) for i, e in enumerate(pad.Shape.Edges, 1)
                if all(abs(v.X - 40) < 1e-9 and abs(v.Y - 25) < 1e-9 for v in e.Vertexes))
    chamfer = body.newObject("PartDesign::Chamfer", "Chamfer")
    chamfer.Base = (pad, [edge])
    chamfer.Size = 8.0
    doc.recompute()
    number, top = max(enumerate(chamfer.Shape.Faces, 1), key=lambda f: f[1].CenterOfMass.z)
    return chamfer, "Face{}".format(number), top


class TestGeneralFaces(unittest.TestCase):
    """Faces with edges at any angle (the core's general engine) in the workbench: decompose, step through,
    the parametric object (undo, save and reopen), write-back, and their quad meshes."""

    def setUp(self):
        self.doc = support.new_document("general")
        self.folder = support.temporary_folder()

    def tearDown(self):
        support.close_document(self.doc)
        support.remove_folder(self.folder)

    def check_blocks(self, shape, face):
        """The blocks tile the face: areas sum to its area, every block a convex quadrilateral or a template."""
        self.assertAlmostEqual(sum(f.Area for f in shape.Faces), face.Area, delta=1e-6 * face.Area)
        self.assertAlmostEqual(shape.Area, face.Area, delta=1e-6 * face.Area)
        self.assertTrue(shape.isValid())
        box, blocks = face.BoundBox, shape.BoundBox
        for a, b in ((box.XMin, blocks.XMin), (box.XMax, blocks.XMax), (box.YMin, blocks.YMin), (box.YMax, blocks.YMax),
                     (box.ZMin, blocks.ZMin), (box.ZMax, blocks.ZMax)):
            self.assertAlmostEqual(a, b, delta=1e-6 * box.DiagonalLength)

    def test_a_sketch_with_slanted_lines_decomposes_into_blocks(self):
        sketch = support.add_slanted_sketch(self.doc)
        face = self.doc.addObject("Part::Face", "SlantedFace")
        face.Sources = [sketch]
        self.doc.recompute()
        self.assertEqual(len(face.Shape.Faces), 1)
        self.assertEqual(len(face.Shape.Faces[0].Wires), 2)  # the outer wire and the hole
        figures = AutoBlock.check_face(face)
        self.assertTrue(figures["general"])
        self.assertIsNone(figures["min_blocks"])
        for policy in ("auto", "greedy", "random"):
            with self.subTest(policy=policy):
                result = AutoBlock.decompose(face, policy=policy)
                self.assertTrue(result.general)
                self.assertTrue(result.complete)
                self.assertEqual(len(result.blocks), result.n_blocks + result.n_templates)
                self.check_blocks(Part.makeCompound(result.blocks), face.Shape)
                self.check_blocks(result.shape, face.Shape)
                self.assertGreater(len(result.cuts), 0)
                self.assertIn(" cut", result.summary())
                self.assertEqual(json.loads(json.dumps(result.to_dict()))["engine"], "general")
        # The sketch itself (closed wires) is taken as well, and gives the same blocks.
        direct = AutoBlock.decompose(sketch, policy="greedy")
        again = AutoBlock.decompose(face, policy="greedy")
        self.assertEqual(len(direct.blocks), len(again.blocks))
        self.assertAlmostEqual(direct.ret, again.ret, places=9)

    def test_a_policy_whose_blocks_do_not_mesh(self):
        """Greedy's blocks of this plate do not mesh: decompose and mesh take the search's instead and say so."""
        path = os.path.join(AutoBlock.paths.ROOT, "tests", "data", "arcs", "greedy-unmeshable.brep")
        face = Part.read(path).Faces[0]
        result = AutoBlock.decompose(face, policy="greedy")
        self.assertEqual(result.policy, "search")
        self.assertEqual(result.policy_fallback["policy"], "greedy")
        self.assertTrue(result.policy_fallback["reason"])
        mesh = AutoBlock.mesh(face, policy="greedy")
        self.assertTrue(mesh.conformal)
        self.assertIsNone(AutoBlock.decompose(face).policy_fallback)

    def test_same_blocks_as_the_cli(self):
        # The workbench and the CLI put a face in the same frame (the core's rule), so they make the same cuts.
        cli = os.environ.get("AUTOBLOCK_CLI")
        if not cli:
            self.skipTest("AUTOBLOCK_CLI not set")
        samples = os.path.join(AutoBlock.paths.MODELS, "data", "general-test-holes")
        for name in ("shape_0000.brep", "shape_0001.brep", "shape_0002.brep"):
            with self.subTest(name=name):
                path = os.path.join(samples, name)
                report = os.path.join(self.folder, name + ".json")
                subprocess.run([cli, "decompose", path, "--policy", "greedy", "--json", report], check=True,
                               capture_output=True)
                with open(report) as f:
                    expected = json.load(f)
                result = AutoBlock.decompose(support.read_face(path), policy="greedy")
                self.assertTrue(result.general)
                self.assertEqual(result.n_blocks, expected["n_blocks"])
                self.assertEqual(result.n_templates, expected["n_templates"])
                self.assertAlmostEqual(result.ret, expected["return"], places=9)
                self.assertEqual([(c.kind, c.local) for c in result.cuts],
                                 [(c["kind"], tuple(c["origin"]) if "origin" in c else None) for c in expected["cuts"]])

    def test_stepping_through_angled_and_partial_cuts(self):
        sketch = support.add_slanted_sketch(self.doc)
        result = AutoBlock.decompose(sketch, policy="greedy")
        stepper = result.stepper()
        self.assertTrue(stepper.general)
        self.assertEqual(stepper.steps, len(result.cuts))
        whole = sum(b.Area for b in result.blocks)
        size = result.face.BoundBox.DiagonalLength
        running, angled, kinds = 0.0, 0, set()
        for k in range(stepper.steps + 1):
            view = stepper.step(k)
            self.assertAlmostEqual(sum(p.face.Area for p in view.pieces), whole, delta=1e-6 * whole)
            self.assertAlmostEqual(view.ret, running, places=9)
            if k == stepper.steps:
                self.assertIsNone(view.next)
                self.assertTrue(all(p.block for p in view.pieces))
                self.assertEqual(len(view.pieces), len(result.blocks))
                break
            cut, step = result.cuts[k], view.next
            self.assertEqual(step.part, cut.part)
            self.assertEqual(step.kind, cut.kind)
            self.assertAlmostEqual(step.reward, cut.reward, places=9)
            running += cut.reward
            self.assertIsNone(step.scores)
            self.assertIn("'greedy' is a baseline", step.scores_note)
            kinds.add(step.kind)
            if cut.kind == "template":
                self.assertIsNone(step.vertex)
                self.assertEqual(step.line, [])
                continue
            self.assertTrue(step.vertex.isEqual(cut.origin, 1e-9))
            self.assertIn("cut at", step.direction)
            if step.chosen >= 0:
                self.assertTrue(step.vertices[step.chosen].isEqual(step.vertex, 1e-6))
            if step.n_parts > 1:
                self.assertGreater(len(step.line), 0)
                # Every chord runs along the cut's direction (given in the face's frame: carried to the model's).
                along = view.frame.Rotation.multVec(FreeCAD.Vector(step.vector[0], step.vector[1], 0))
                along.normalize()
                for a, b in step.line:
                    d = b - a
                    self.assertLess(d.cross(along).Length, 1e-6 * size)  # ends rounded to the face's lattice
                    if abs(along.x) > 1e-6 and abs(along.y) > 1e-6:
                        angled += 1
        self.assertGreater(angled, 0, "no cut at an angle other than the axes")
        self.assertTrue(kinds & {"full", "partial"})
        # A cut that does not belong to the face is a ValueError, not a wrong picture.
        spec = list(result.cuts[0].spec())
        spec[2] += 1000.0
        from AutoBlock.stepping import Stepper

        bad = Stepper(stepper.local_brep, stepper.frame, [tuple(spec)], stepper.max_steps, "bad", "greedy")
        with self.assertRaisesRegex(ValueError, "does not belong to this face"):
            bad.step(1)
        # A lookahead agent's trained policy takes general faces; the paper's agent is a clear ValueError.
        learned = AutoBlock.decompose(sketch, policy="sac-mesh")
        self.assertEqual(learned.policy, "sac-mesh")
        self.assertTrue(learned.complete)
        # Its value scores in the step-through view: one per vertex of the part; its chosen vertex scores best.
        first = learned.stepper().step(0).next
        self.assertEqual(first.scores_note, "")
        self.assertEqual(len(first.scores), len(first.vertices))
        finite = [s for s in first.scores if s is not None]
        self.assertTrue(finite)
        if first.chosen >= 0:
            self.assertEqual(first.scores[first.chosen], max(finite))
        with self.assertRaisesRegex(ValueError, "edges at other angles"):
            AutoBlock.decompose(sketch, policy="sac-faithful")
        # The blocks meshed with quads (the general mesher: block model, intervals, transfinite, smoothing):
        # conformal by the core's check, every quad counter-clockwise in the face's plane, areas adding up.
        mesh = AutoBlock.mesh(result)
        self.assertTrue(mesh.conformal)
        self.assertGreater(len(mesh.quads), len(result.blocks))
        self.assertGreater(mesh.quality["min_scaled_jacobian"], 0.0)
        self.assertLessEqual(mesh.quality["bound"], 1.0)
        area = sum(Part.Face(Part.makePolygon([mesh.nodes[i] for i in q] + [mesh.nodes[q[0]]])).Area for q in mesh.quads)
        self.assertAlmostEqual(area, whole, delta=1e-6 * whole)

    def test_a_chamfered_box_gets_its_top_face_split_into_the_blocks_in_place(self):
        # Part's chamfer on a box (a plain Part feature holding the solid): write-back "replace" splits its top face.
        box = Part.makeBox(30, 20, 6)
        edge = next(e for e in box.Edges if e.BoundBox.ZLength > 1 and e.BoundBox.XMin > 29 and e.BoundBox.YMin > 19)
        solid = box.makeChamfer(7.0, [edge])
        holder = support.add_face(self.doc, solid, "ChamferedBox")
        number, top = max(enumerate(solid.Faces, 1), key=lambda f: f[1].CenterOfMass.z)
        self.assertEqual(len(top.Vertexes), 5)
        obj = AutoBlock.make_autoblock(holder, "Face{}".format(number), policy="greedy")
        self.check_blocks(obj.Shape, top)
        blocks = len(obj.Shape.Faces)
        self.assertGreater(blocks, 1)
        AutoBlock.write_back(obj, "replace")
        self.assertEqual(len(holder.Shape.Solids), 1)
        self.assertTrue(holder.Shape.isValid())
        # The blocks' corners lie on the face's lattice (within its tolerance): the volume agrees to that.
        self.assertAlmostEqual(holder.Shape.Volume, solid.Volume, delta=1e-8 * solid.Volume)
        self.assertEqual(len(holder.Shape.Faces), len(solid.Faces) - 1 + blocks)
        self.doc.undo()
        self.assertEqual(len(holder.Shape.Faces), len(solid.Faces))

    def test_a_reopened_object_replays_its_cuts_instead_of_searching_again(self):
        from AutoBlock import console

        sketch = support.add_slanted_sketch(self.doc)
        obj = AutoBlock.make_autoblock(sketch)  # auto: the general engine's search, with its time budget
        name, areas, ret = obj.Name, sorted(f.Area for f in obj.Shape.Faces), obj.Return
        path = os.path.join(self.folder, "replay.FCStd")
        self.doc.saveAs(path)
        FreeCAD.closeDocument(self.doc.Name)
        self.doc = FreeCAD.openDocument(path)
        obj, sketch = self.doc.getObject(name), self.doc.getObject("Slanted")
        searched = []
        original = console.decompose
        console.decompose = lambda *args, **kwargs: searched.append(args) or original(*args, **kwargs)
        self.addCleanup(setattr, console, "decompose", original)
        obj.touch()
        self.doc.recompute()
        self.assertEqual(searched, [])  # replayed from CutSequence
        self.assertIn("Up-to-date", obj.State)
        self.assertEqual(len(obj.Shape.Faces), len(areas))
        for a, b in zip(sorted(f.Area for f in obj.Shape.Faces), areas):
            self.assertAlmostEqual(a, b, places=6)
        self.assertAlmostEqual(obj.Return, ret, places=9)
        # The console twin gives the same blocks.
        again = AutoBlock.replay(sketch, obj.CutSequence)
        self.assertTrue(again.general)
        self.assertAlmostEqual(again.ret, ret, places=9)
        # Another face (the sketch moved: a general face in the XY plane keeps the model's coordinates), other
        # settings: decomposed again; the old cuts do not replay on another face.
        sketch.Placement.Base = FreeCAD.Vector(5, 0, 0)
        self.doc.recompute()
        self.assertEqual(len(searched), 1)
        self.assertAlmostEqual(obj.Shape.BoundBox.XMin, sketch.Shape.BoundBox.XMin, delta=1e-4)  # lattice: 1e-5
        obj.touch()
        self.doc.recompute()
        self.assertEqual(len(searched), 1)  # replayed again
        obj.Seed = 7
        self.doc.recompute()
        self.assertEqual(len(searched), 2)
        other = support.add_face(self.doc, Part.Face(Part.makePolygon([FreeCAD.Vector(*p) for p in (
            (0, 0, 0), (30, 0, 0), (36, 9, 0), (30, 20, 0), (0, 20, 0), (0, 0, 0))])), "Other")
        stored = obj.CutSequence
        obj.Source = (other, [])
        self.doc.recompute()
        self.assertEqual(len(searched), 3)
        self.check_blocks(obj.Shape, other.Shape)
        with self.assertRaisesRegex(ValueError, "not the face this cut sequence was made on"):
            AutoBlock.replay(other, stored)
        with self.assertRaisesRegex(ValueError, "engine 'general'"):
            AutoBlock.replay(support.l_face(), AutoBlock.decompose(support.l_face()).cut_sequence())

    def test_a_chamfered_pad_face_as_a_parametric_object(self):
        chamfer, top_name, top = add_chamfered_pad(self.doc)
        self.assertEqual(len(top.Vertexes), 5)  # the rectangle with one corner cut off
        self.assertAlmostEqual(top.Area, 40 * 25 - 32.0, places=6)
        from AutoBlock.objects.fem_mesh import is_autoblock_mesh

        count = len(self.doc.Objects)
        undo_count = self.doc.UndoCount
        # Through its Body, as Auto-Block on a selected face does (the link stays within the Body's scope).
        body = self.doc.getObject("Body")
        obj = AutoBlock.make_autoblock(body, "Chamfer." + top_name, policy="greedy")
        self.assertEqual(self.doc.UndoCount, undo_count + 1)
        self.assertEqual(self.doc.UndoNames[0], "Auto-Block")
        self.assertIn("Up-to-date", obj.State)
        self.check_blocks(obj.Shape, top)
        self.assertEqual(len(obj.Shape.Faces), obj.NumberOfBlocks)
        self.assertEqual(obj.MinimumBlocks, 0)
        self.assertGreater(obj.NumberOfCuts, 0)
        self.assertIn("greedy: ", obj.Status)
        self.assertEqual(json.loads(obj.CutSequence)["engine"], "general")
        # Its FEM mesh object, made with it in the same transaction: the general mesher's quads cover the face.
        meshes = [o for o in self.doc.Objects if is_autoblock_mesh(o)]
        self.assertEqual(len(meshes), 1)
        self.assertIs(AutoBlock.mesh(obj), meshes[0])
        self.assertGreater(meshes[0].FemMesh.QuadrangleCount, obj.NumberOfBlocks)
        self.assertEqual(meshes[0].FemMesh.TriangleCount, 0)
        # Undo and redo.
        name = obj.Name
        self.doc.undo()
        self.assertIsNone(self.doc.getObject(name))
        self.assertEqual(len(self.doc.Objects), count)
        self.doc.redo()
        obj = self.doc.getObject(name)
        self.doc.recompute()
        self.check_blocks(obj.Shape, top)
        # The chamfer grows: the object follows.
        chamfer.Size = 12.0
        self.doc.recompute()
        top = chamfer.Shape.getElement(top_name)
        self.assertAlmostEqual(top.Area, 40 * 25 - 72.0, places=6)
        self.check_blocks(obj.Shape, top)
        blocks, ret, cuts = obj.NumberOfBlocks, obj.Return, obj.NumberOfCuts
        # Save, reopen, step through the stored sequence, recompute, write back.
        path = os.path.join(self.folder, "general.FCStd")
        self.doc.saveAs(path)
        FreeCAD.closeDocument(self.doc.Name)
        self.doc = FreeCAD.openDocument(path)
        self.doc.UndoMode = 1  # a reopened document starts without undo
        obj, chamfer = self.doc.getObject(name), self.doc.getObject("Chamfer")
        self.assertTrue(AutoBlock.is_autoblock(obj))
        stepper = AutoBlock.stepper_of(obj)
        self.assertTrue(stepper.general)
        self.assertEqual(stepper.steps, cuts)
        last = stepper.step(stepper.steps)
        self.assertEqual(len(last.pieces), blocks)
        self.assertAlmostEqual(last.ret, ret, places=9)
        obj.touch()
        self.doc.recompute()
        self.assertIn("Up-to-date", obj.State)
        self.assertEqual(obj.NumberOfBlocks, blocks)
        self.assertAlmostEqual(obj.Return, ret, places=9)
        self.check_blocks(obj.Shape, chamfer.Shape.getElement(top_name))
        undo_count = self.doc.UndoCount
        feature = AutoBlock.write_back(obj, mode="new")
        self.assertEqual(self.doc.UndoCount, undo_count + 1)
        self.assertEqual(len(feature.Shape.Faces), blocks)
        self.check_blocks(feature.Shape, chamfer.Shape.getElement(top_name))
        feature_name = feature.Name
        self.doc.undo()
        self.assertIsNone(self.doc.getObject(feature_name))


def add_filleted_pad(doc):
    """add_rectangle_pad's Pad with its two vertical edges at x = 40 filleted (radius 6): returns (fillet, name
    of its top face, the top face)."""
    body, pad = add_rectangle_pad(doc)
    edges = ["Edge{}".format(i) for i, e in enumerate(pad.Shape.Edges, 1)
             if abs(e.Vertexes[0].Z - e.Vertexes[1].Z) > 1 and abs(e.Vertexes[0].X - 40) < 1e-9]
    fillet = body.newObject("PartDesign::Fillet", "Fillet")
    fillet.Base = (pad, edges)
    fillet.Radius = 6.0
    doc.recompute()
    number, top = max(enumerate(fillet.Shape.Faces, 1), key=lambda f: f[1].CenterOfMass.z)
    return fillet, "Face{}".format(number), top


class TestArcFaces(unittest.TestCase):
    """Faces with circular arcs (issue 13): a filleted Pad's top as a parametric object, a plate with drilled
    holes meshed from the console, every boundary node on its arc."""

    def setUp(self):
        self.doc = support.new_document("arcs")

    def tearDown(self):
        support.close_document(self.doc)

    def check_nodes_on_circles(self, mesh, circles, holes=False):
        """Returns how many mesh nodes lie on one of the circles; for holes, also checks that no node lies
        inside one."""
        on = 0
        for node in mesh.nodes:
            for centre, r in circles:
                d = (node - centre).Length
                if holes:
                    self.assertGreater(d, r - 1e-6 * r)
                on += abs(d - r) < 1e-6 * r
        return on

    def test_a_filleted_pad_face_as_a_parametric_object(self):
        fillet, top_name, top = add_filleted_pad(self.doc)
        self.assertAlmostEqual(top.Area, 40 * 25 - 2 * (36 - 3.141592653589793 * 9), places=6)
        body = self.doc.getObject("Body")
        obj = AutoBlock.make_autoblock(body, "Fillet." + top_name, policy="greedy")
        self.assertIn("Up-to-date", obj.State)
        self.assertEqual(json.loads(obj.CutSequence)["engine"], "general")
        # OpenCASCADE's blocks, cut from the true face, cover it.
        self.assertAlmostEqual(sum(f.Area for f in obj.Shape.Faces), top.Area, delta=1e-6 * top.Area)
        self.assertTrue(obj.Shape.isValid())
        mesh = AutoBlock.mesh(top, size=1.0)
        self.assertTrue(mesh.conformal)
        circles = [(e.Curve.Center, e.Curve.Radius) for e in top.Edges if isinstance(e.Curve, Part.Circle)]
        self.assertEqual(len(circles), 2)
        # Nodes on the fillets' arcs (not on chords): at least one per unit of arc length.
        self.assertGreaterEqual(self.check_nodes_on_circles(mesh, circles), 2 * int(3.141592653589793 * 6 / 2))

    @staticmethod
    def drilled_plate_top():
        """A 30 x 12 x 2 plate with two drilled holes: its top face, and the holes (centre at z = 0, radius)."""
        V = FreeCAD.Vector
        plate = Part.makeBox(30, 12, 2)
        holes = [(V(7, 6, 0), 2.5), (V(20, 5, 0), 1.5)]
        for centre, r in holes:
            plate = plate.cut(Part.makeCylinder(r, 4, centre + V(0, 0, -1)))
        return max(plate.Faces, key=lambda f: f.CenterOfMass.z), holes

    def test_a_plate_with_drilled_holes_meshes_with_nodes_on_the_holes(self):
        V = FreeCAD.Vector
        top, holes = self.drilled_plate_top()
        self.assertEqual(len(top.Wires), 3)
        mesh = AutoBlock.mesh(top)
        self.assertTrue(mesh.conformal)
        on = self.check_nodes_on_circles(mesh, [(c + V(0, 0, 2), r) for c, r in holes], holes=True)
        self.assertGreaterEqual(on, 24 * 2)  # at least the holes' polygons' directions
        area = 0.0
        for a, b, c, d in mesh.quads:
            area += ((mesh.nodes[c] - mesh.nodes[a]).cross(mesh.nodes[d] - mesh.nodes[b])).Length / 2
        # The quads' chords cut across the holes a little: a little more area than the face, shrinking with h.
        self.assertGreater(area, top.Area)
        self.assertLess(area, top.Area * 1.01)

    def test_a_perforated_plate_is_divided_along_its_ligaments_one_o_grid_per_hole(self):
        """A plate drilled with a 4 x 3 grid of holes: divided along the ligaments between them into one square cell
        per hole, each an O-grid, whose least scaled Jacobian is that of a plate with one hole (the five-valent
        box corners: sin 72 degrees less smoothing's gain)."""
        V = FreeCAD.Vector
        plate = Part.makeBox(40, 30, 2)
        holes = [(V(5 + 10 * i, 5 + 10 * j, 0), 1.5) for i in range(4) for j in range(3)]
        for centre, r in holes:
            plate = plate.cut(Part.makeCylinder(r, 4, centre + V(0, 0, -1)))
        top = max(plate.Faces, key=lambda f: f.CenterOfMass.z)
        self.assertEqual(len(top.Wires), 13)
        mesh = AutoBlock.mesh(top, size=1.0)
        self.assertTrue(mesh.conformal)
        self.assertGreater(mesh.quality["min_scaled_jacobian"], 0.9)
        self.assertGreaterEqual(self.check_nodes_on_circles(mesh, [(c + V(0, 0, 2), r) for c, r in holes], holes=True), 12 * 24)
        # Every cell's O-grid has the same four five-valent corners: 48 irregular vertices, no other.
        self.assertEqual(mesh.quality["irregular_interior_vertices"], 48)

    def test_a_flange_is_divided_into_one_sector_per_bolt_hole(self):
        """A flange (a disk of radius 50 with a bore of radius 20 and eight bolt holes on a circle of radius 36):
        no straight line misses both the bore and the bolt circle, so the division runs along radial lines between
        the bolt holes, cutting the bore across. Its sectors mesh above 0.9 (0.85 when the search cut the disk
        itself, crossing the bolt circle)."""
        V = FreeCAD.Vector
        flange = Part.makeCylinder(50, 2).cut(Part.makeCylinder(20, 4, V(0, 0, -1)))
        holes = [(V(36 * math.cos(i * math.pi / 4), 36 * math.sin(i * math.pi / 4), 0), 3.0) for i in range(8)]
        for centre, r in holes:
            flange = flange.cut(Part.makeCylinder(r, 4, centre + V(0, 0, -1)))
        top = max(flange.Faces, key=lambda f: f.CenterOfMass.z)
        self.assertEqual(len(top.Wires), 10)
        mesh = AutoBlock.mesh(top)
        self.assertTrue(mesh.conformal)
        self.assertGreater(mesh.quality["min_scaled_jacobian"], 0.9)
        circles = [(c + V(0, 0, 2), r) for c, r in holes] + [(V(0, 0, 2), 20.0)]
        self.assertGreaterEqual(self.check_nodes_on_circles(mesh, circles, holes=True), 9 * 24)

    def test_a_face_whose_curves_are_b_splines_meshes_as_its_lines_and_circles(self):
        """Many translators write circles and lines as B-splines (CATIA's drilled holes): such a face is read as
        the lines and circles it is, and meshes as the same face made of them does."""
        V = FreeCAD.Vector
        top, holes = self.drilled_plate_top()
        nurbs = top.toNurbs().Faces[0]
        self.assertTrue(all(e.Curve.__class__.__name__ == "BSplineCurve" for e in nurbs.Edges))
        mesh = AutoBlock.mesh(nurbs)
        self.assertTrue(mesh.conformal)
        self.assertGreaterEqual(self.check_nodes_on_circles(mesh, [(c + V(0, 0, 2), r) for c, r in holes], holes=True), 24 * 2)
        self.assertEqual(len(mesh.quads), len(AutoBlock.mesh(top).quads))

    def test_the_end_of_a_tilted_tube_a_face_without_a_straight_edge(self):
        """A washer bounded by two circles in a tilted plane has no straight edge to set its frame by: it takes its
        plane's, and its blocks and mesh come back in the model's plane."""
        V = FreeCAD.Vector
        tube = Part.makeCylinder(8, 5).cut(Part.makeCylinder(3, 5))
        tube.rotate(V(0, 0, 0), V(1, 2, 3), 37)
        end = min(tube.Faces, key=lambda f: f.CenterOfMass.Length if f.Surface.__class__.__name__ == "Plane" else 1e9)
        self.assertEqual(len(end.Wires), 2)
        normal = end.normalAt(0, 0)
        self.assertLess(abs(normal.z), 0.99)  # tilted
        source = support.add_face(self.doc, end, "TubeEnd")
        obj = AutoBlock.make_autoblock(source, policy="greedy")
        self.assertIn("Up-to-date", obj.State)
        self.assertAlmostEqual(sum(f.Area for f in obj.Shape.Faces), end.Area, delta=1e-6 * end.Area)
        mesh = AutoBlock.mesh(end)
        self.assertTrue(mesh.conformal)
        centre = end.Edges[0].Curve.Center
        for node in mesh.nodes:
            self.assertLess(abs((node - centre).dot(normal)), 1e-6)  # in the face's plane
            self.assertGreater((node - centre).Length, 3 - 1e-6)
            self.assertLess((node - centre).Length, 8 + 1e-6)

    def test_the_workbench_meshes_an_arc_face_as_the_cli_does(self):
        """The search's tries (other widths and block rules, finer edges) reach the workbench: what decompose keeps
        is what `autoblock mesh` keeps, stored with its rules, and meshed the same from the console, from an
        AutoBlock object and after its cuts are replayed."""
        cli = os.environ.get("AUTOBLOCK_CLI")
        if not cli:
            self.skipTest("AUTOBLOCK_CLI not set")
        V = FreeCAD.Vector
        plate = Part.makeBox(25, 25, 2)
        for centre in (V(8, 8, -1), V(17, 17, -1)):  # two holes on the diagonal: the first try is poor
            plate = plate.cut(Part.makeCylinder(4, 4, centre))
        top = max(plate.Faces, key=lambda f: f.CenterOfMass.z)
        folder = support.temporary_folder()
        self.addCleanup(support.remove_folder, folder)
        path, report = os.path.join(folder, "plate.brep"), os.path.join(folder, "mesh.json")
        top.exportBrep(path)
        subprocess.run([cli, "mesh", path, "--json", report], check=True, capture_output=True, timeout=300)
        with open(report) as f:
            expected = json.load(f)
        result = AutoBlock.decompose(top)
        self.assertEqual(result.min_edge_intervals, expected["min_edge_intervals"])
        self.assertEqual(len(result.rules), 3)
        mesh = AutoBlock.mesh(result)
        self.assertEqual(len(mesh.quads), expected["quads"])
        self.assertAlmostEqual(mesh.quality["min_scaled_jacobian"], expected["quality"]["min_scaled_jacobian"], places=9)
        # An object stores the rules with its cuts; its FEM mesh, and a replay of the stored cuts, are the same.
        source = support.add_face(self.doc, top, "Plate")
        obj = AutoBlock.make_autoblock(source)
        stored = json.loads(obj.CutSequence)
        self.assertEqual(stored["rules"], result.rules)
        self.assertEqual(stored["min_edge_intervals"], expected["min_edge_intervals"])
        self.assertEqual(AutoBlock.mesh(obj).NumberOfQuads, expected["quads"])
        again = AutoBlock.replay(source, obj.CutSequence)
        self.assertEqual(again.n_blocks, result.n_blocks)
        self.assertEqual(len(AutoBlock.mesh(again).quads), expected["quads"])
        # A sequence stored before the rules were (none in it) replays under the face's own rules, one interval.
        from AutoBlock import console

        old = dict(stored)
        del old["rules"], old["min_edge_intervals"]
        self.assertEqual(console.sequence_rules(old), [])
        self.assertEqual(console.sequence_min_edge_intervals(old), 1)


class TestFemMesh(unittest.TestCase):
    def test_quads_become_a_fem_mesh_object(self):
        from AutoBlock.objects.fem_mesh import make_fem_mesh_object

        doc = support.new_document("fem")
        try:
            # A 2 x 1 strip of unit quads.
            nodes = [(0, 0, 0), (1, 0, 0), (2, 0, 0), (0, 1, 0), (1, 1, 0), (2, 1, 0)]
            quads = [(0, 1, 4, 3), (1, 2, 5, 4)]
            obj = make_fem_mesh_object(doc, nodes, quads)
            self.assertEqual(obj.TypeId, "Fem::FemMeshObject")
            self.assertEqual(obj.FemMesh.NodeCount, 6)
            self.assertEqual(obj.FemMesh.QuadrangleCount, 2)
            for bad in ([(0, 1, 4)], [(0, 1, 1, 3)], [(0, 1, 4, 9)]):
                with self.assertRaises(ValueError):
                    make_fem_mesh_object(doc, nodes, bad)
        finally:
            support.close_document(doc)

    def test_auto_block_objects_get_a_fem_mesh_that_follows_them(self):
        from AutoBlock.objects.fem_mesh import is_autoblock_mesh

        doc = support.new_document("fem")
        try:
            source = support.add_face(doc, support.read_face())
            undo_count = doc.UndoCount
            obj = AutoBlock.make_autoblock(source, mesh_size=1.0)
            meshes = [o for o in doc.Objects if is_autoblock_mesh(o)]
            self.assertEqual(len(meshes), 1)
            mesh = meshes[0]
            self.assertEqual(mesh.TypeId, "Fem::FemMeshObjectPython")
            self.assertIs(mesh.AutoBlock, obj)
            self.assertIs(AutoBlock.mesh(obj), mesh)  # the object's mesh, not a second one
            self.assertEqual(doc.UndoCount, undo_count + 1)  # object and mesh: one transaction
            femmesh = mesh.FemMesh
            self.assertEqual(femmesh.QuadrangleCount, mesh.NumberOfQuads)
            self.assertEqual(femmesh.NodeCount, mesh.NumberOfNodes)
            self.assertGreater(mesh.NumberOfQuads, obj.NumberOfBlocks)
            self.assertIn("min scaled Jacobian 1, conformal", mesh.Quality)
            # Same mesh as the console's of the same decomposition and size.
            expected = AutoBlock.mesh(AutoBlock.decompose(source), size=1.0)
            self.assertEqual(mesh.NumberOfQuads, len(expected.quads))
            self.assertAlmostEqual(femmesh.BoundBox.XLength, source.Shape.BoundBox.XLength, places=9)
            # The mesh size drives it; recompute updates it.
            coarse = mesh.NumberOfQuads
            obj.MeshSize = 0.5
            doc.recompute()
            self.assertIn("Up-to-date", mesh.State)
            self.assertGreater(mesh.NumberOfQuads, 3 * coarse)
            self.assertAlmostEqual(mesh.TargetSize, 0.5)
            # So does the source.
            source.Placement.Base = FreeCAD.Vector(0, 0, 4)
            doc.recompute()
            self.assertAlmostEqual(mesh.FemMesh.BoundBox.ZMin, 4.0)
            # AutoBlock.mesh(obj, size) changes the size, one undoable step.
            undo_count = doc.UndoCount
            AutoBlock.mesh(obj, size=2.0)
            self.assertAlmostEqual(mesh.TargetSize, 2.0)
            self.assertEqual(doc.UndoCount, undo_count + 1)
            self.assertEqual(doc.UndoNames[0], "AutoBlock mesh")
            # A size asking for too many quads is refused; nothing changes.
            quads = mesh.NumberOfQuads
            with self.assertRaisesRegex(ValueError, "quadrilaterals"):
                AutoBlock.mesh(obj, size=1e-4)
            self.assertAlmostEqual(float(obj.MeshSize), 2.0)
            self.assertEqual(mesh.NumberOfQuads, quads)
            # Undo of the Auto-Block removes the mesh with its object.
            names = [o.Name for o in doc.Objects]
            AutoBlock.make_autoblock(source, policy="optimal")
            self.assertEqual(len(doc.Objects), len(names) + 2)
            doc.undo()
            self.assertEqual([o.Name for o in doc.Objects], names)
            # mesh=False: no mesh object.
            AutoBlock.make_autoblock(source, mesh=False)
            self.assertEqual(len([o for o in doc.Objects if is_autoblock_mesh(o)]), 1)
        finally:
            support.close_document(doc)

    def test_an_incomplete_decomposition_gets_no_mesh(self):
        doc = support.new_document("truncated")
        try:
            face = support.read_face()
            result = AutoBlock.decompose(face, policy="optimal", max_steps=1)
            self.assertTrue(result.truncated)
            with self.assertRaisesRegex(ValueError, "incomplete"):
                AutoBlock.mesh(result)
        finally:
            support.close_document(doc)


class TestMeshes(unittest.TestCase):
    def setUp(self):
        self.folder = support.temporary_folder()

    def tearDown(self):
        support.remove_folder(self.folder)

    def test_mesh_a_decomposition(self):
        face = support.read_face()
        result = AutoBlock.decompose(face, policy="optimal")
        mesh = AutoBlock.mesh(result, size=0.5)
        self.assertIs(mesh.decomposition, result)
        self.assertEqual(mesh.n_blocks, result.n_blocks)
        self.assertTrue(mesh.conformal)
        self.assertEqual(mesh.quality["min_scaled_jacobian"], 1.0)  # rectilinear blocks: exact rectangles
        self.assertEqual(mesh.quality["irregular_interior_vertices"], 0)
        self.assertAlmostEqual(mesh.target_size, 0.5)
        self.assertEqual(sorted(set(mesh.quad_block)), list(range(result.n_blocks)))
        area = 0.0
        for a, b, c, d in mesh.quads:
            self.assertEqual(len({a, b, c, d}), 4)
            area += ((mesh.nodes[c] - mesh.nodes[a]).cross(mesh.nodes[d] - mesh.nodes[b])).Length / 2
        self.assertAlmostEqual(area, face.Area, places=6)
        self.assertIsInstance(mesh.nodes[0], FreeCAD.Vector)
        self.assertEqual(mesh.fem_mesh().QuadrangleCount, len(mesh.quads))
        # A face straight away (decomposed with the default policy), and the automatic size.
        auto = AutoBlock.mesh(face)
        self.assertEqual(auto.decomposition.policy, "auto")
        box = face.BoundBox
        self.assertAlmostEqual(auto.target_size, max(box.XLength, box.YLength) / 20)

    def test_same_mesh_as_the_cli(self):
        cli = os.environ.get("AUTOBLOCK_CLI")
        if not cli:
            self.skipTest("AUTOBLOCK_CLI not set")
        report = os.path.join(self.folder, "mesh.json")
        subprocess.run([cli, "mesh", support.SAMPLE, "--json", report], check=True, capture_output=True)
        with open(report) as f:
            expected = json.load(f)
        mesh = AutoBlock.mesh(support.read_face())
        self.assertEqual(len(mesh.quads), expected["quads"])
        self.assertEqual(len(mesh.nodes), expected["nodes"])
        self.assertEqual(mesh.n_blocks, expected["blocks"])

    def test_export_in_every_format_where_the_face_lies(self):
        doc = support.new_document("export")
        try:
            # An L-shaped sketch standing in the plane y = 5: the files must say y = 5 for every node.
            placement = FreeCAD.Placement(FreeCAD.Vector(0, 5, 0), FreeCAD.Rotation(FreeCAD.Vector(1, 0, 0), 90))
            sketch = support.add_l_sketch(doc, placement)
            obj = AutoBlock.make_autoblock(sketch, mesh_size=0.5)
            mesh_object = AutoBlock.mesh(obj)
            inp = os.path.join(self.folder, "l.inp")
            result = AutoBlock.export_mesh(obj, inp)
            self.assertEqual(result.file, inp)
            with open(inp) as f:
                lines = f.read().split("*NODE, NSET=NALL\n")[1].split("*")[0].splitlines()
            self.assertEqual(len(lines), mesh_object.NumberOfNodes)
            ys = [float(line.split(",")[2]) for line in lines]
            self.assertAlmostEqual(min(ys), 5.0, places=9)
            self.assertAlmostEqual(max(ys), 5.0, places=9)
            zs = [float(line.split(",")[3]) for line in lines]
            self.assertAlmostEqual(max(zs) - min(zs), 4.0, places=9)
            msh = os.path.join(self.folder, "l.msh")
            AutoBlock.export_mesh(mesh_object, msh)  # the mesh object exports its AutoBlock object's mesh
            with open(msh) as f:
                text = f.read()
            self.assertIn('"block_1"', text)
            self.assertIn('"block_2"', text)
            vtu = os.path.join(self.folder, "l.vtu")
            AutoBlock.export_mesh(AutoBlock.mesh(AutoBlock.decompose(sketch), size=0.5), vtu)
            with open(vtu) as f:
                self.assertIn('NumberOfCells="{}"'.format(mesh_object.NumberOfQuads), f.read())
            with self.assertRaisesRegex(ValueError, "expected a .msh, .vtu or .inp"):
                AutoBlock.export_mesh(obj, os.path.join(self.folder, "l.stl"))
            with self.assertRaisesRegex(ValueError, "does not exist"):
                AutoBlock.export_mesh(obj, "/no/such/folder/l.msh")
            self.assertFalse(os.path.exists(os.path.join(self.folder, "l.stl")))
        finally:
            support.close_document(doc)


class TestTraining(unittest.TestCase):
    def test_requests_are_checked(self):
        folder = support.temporary_folder()
        try:
            data = dict(train_folder=support.SAMPLES, test_folder=support.SAMPLES)
            good = AutoBlock.TrainingRequest(os.path.join(folder, "p.pt"), **data)
            good.validate()
            generated = AutoBlock.TrainingRequest(os.path.join(folder, "p.pt"),
                                                  train_generate={"count": 5, "min_rects": 2, "max_rects": 4},
                                                  test_folder=support.SAMPLES)
            generated.validate()
            self.assertEqual(generated.to_options()["train_generate"]["count"], 5)
            self.assertEqual(eval(repr(generated), {"AutoBlock": AutoBlock}).to_options(), generated.to_options())
            cases = [
                (AutoBlock.TrainingRequest(os.path.join(folder, "p.pt"), test_folder=support.SAMPLES),
                 "no training data"),
                (AutoBlock.TrainingRequest(os.path.join(folder, "p.pt"), train_folder=support.SAMPLES), "no test data"),
                (AutoBlock.TrainingRequest("/no/such/dir/p.pt", **data), "does not exist"),
                (AutoBlock.TrainingRequest(os.path.join(folder, "p.pt"), train_folder="/no/such",
                                           test_folder=support.SAMPLES), "no such folder"),
                (AutoBlock.TrainingRequest(os.path.join(folder, "p.pt"), episodes=0, **data), "at least 1"),
                (AutoBlock.TrainingRequest(os.path.join(folder, "p.pt"), reward="nope", **data), "unknown reward"),
                (AutoBlock.TrainingRequest(os.path.join(folder, "p.pt"), resume=True, **data), "nothing to resume"),
                (AutoBlock.TrainingRequest(os.path.join(folder, "p.pt"), resume=True, init="sac-mesh", **data),
                 "starts a fresh run"),
                (AutoBlock.TrainingRequest(os.path.join(folder, "p.pt"), train_generate={"count": 0, "general": 0},
                                           test_folder=support.SAMPLES), "at least one shape"),
            ]
            for request, words in cases:
                with self.subTest(words=words):
                    with self.assertRaisesRegex(ValueError, words):
                        request.validate()
            # A warm start: its repr keeps it; the core refuses another agent kind's policy.
            warm = AutoBlock.TrainingRequest(os.path.join(folder, "w.pt"), init="sac-faithful", episodes=1,
                                             train_generate={"count": 2, "max_rects": 3, "seed": 1},
                                             test_generate={"count": 1, "max_rects": 3, "seed": 2})
            warm.validate()
            self.assertEqual(eval(repr(warm), {"AutoBlock": AutoBlock}).to_options(), warm.to_options())
            with self.assertRaisesRegex(ValueError, "paper agent's"):
                AutoBlock.train(warm)
            self.assertFalse(os.path.exists(os.path.join(folder, "w.pt")))
        finally:
            support.remove_folder(folder)

    def test_the_core_trains(self):
        from AutoBlock import training

        self.assertTrue(AutoBlock.capabilities()["training"])
        self.assertIs(training.training_backend(), training.NativeTrainingRun)

    def test_a_tiny_training_run_cancelled_resumed_and_used(self):
        """A real run of the core's trainer: a few episodes on 3 generated shapes, cancelled from the progress
        callback, resumed from its checkpoint, and its policy used like a shipped one."""
        folder = support.temporary_folder()
        try:
            output = os.path.join(folder, "tiny.pt")
            request = AutoBlock.TrainingRequest(output, train_generate={"count": 3, "max_rects": 4, "seed": 1},
                                                test_generate={"count": 2, "max_rects": 4, "seed": 2},
                                                episodes=6, eval_every=2, reward="mesh", seed=3)
            events = []

            def progress(event):
                if event.status:  # what the run computes before its first episode
                    statuses.append(event.status)
                    return True
                events.append(event)
                return len(events) < 3  # cancel after the third episode

            statuses = []

            result = AutoBlock.train(request, progress)
            self.assertTrue(result["cancelled"])
            self.assertEqual(result["episodes_done"], 3)
            self.assertEqual(len(statuses), 1)
            self.assertIsNone(result["policy_file"])
            self.assertTrue(os.path.exists(request.checkpoint))
            self.assertFalse(os.path.exists(output))
            self.assertEqual([e.episode for e in events], [1, 2, 3])
            self.assertEqual([e.test_return is not None for e in events], [False, True, False])
            self.assertAlmostEqual(events[1].train_return, (events[0].episode_return + events[1].episode_return) / 2)
            # Resume: the history comes first (earlier), then the remaining episodes.
            request.resume = True
            events = []
            result = AutoBlock.train(request, events.append)
            # First a status event (the reference returns are computed again), then the episodes.
            self.assertIn("reference returns", events[0].status)
            self.assertEqual(events[0].episode, 0)
            events = events[1:]
            self.assertFalse(result["cancelled"])
            self.assertEqual([(e.episode, e.earlier) for e in events],
                             [(1, True), (2, True), (3, True), (4, False), (5, False), (6, False)])
            self.assertEqual(result["policy_file"], output)
            self.assertEqual(result["reward"], "mesh")
            for name in ("log", "curves"):
                self.assertTrue(os.path.getsize(result[name]) > 0)
            with open(result["log"]) as f:
                self.assertEqual(len(f.read().splitlines()), 1 + 6)
            # The trained policy: its own reward, value scores, a parametric object.
            self.assertEqual(AutoBlock.policy_info(output), {"name": output, "learned": True, "reward": "mesh",
                                                             "scores_by": output, "general_network": False})

            decomposition = AutoBlock.decompose(support.read_face(), policy=output)
            self.assertTrue(decomposition.complete)
            self.assertEqual(decomposition.reward, "mesh")
            self.assertEqual(len(decomposition.stepper().step(0).next.scores),
                             len(decomposition.stepper().step(0).next.vertices))
            doc = support.new_document("trained")
            try:
                obj = AutoBlock.make_autoblock(support.add_face(doc, support.read_face()), policy=output)
                self.assertEqual(obj.PolicyFile, output)
                self.assertEqual(obj.NumberOfBlocks, decomposition.n_blocks)
            finally:
                support.close_document(doc)
            # In the background (what the Train panel starts): the same run, polled.
            run = AutoBlock.start_training(AutoBlock.TrainingRequest(
                os.path.join(folder, "background.pt"), train_generate={"count": 3, "max_rects": 4, "seed": 1},
                test_generate={"count": 2, "max_rects": 4, "seed": 2}, episodes=4, eval_every=2))
            run.wait(120)
            self.assertTrue(run.done)
            self.assertIsNone(run.error)
            events = run.poll()
            # First what the run computes before its first episode (a status event), then the episodes.
            self.assertIn("reference returns of the test faces", events[0].status)
            self.assertIn("reference returns", repr(events[0]))
            self.assertEqual([e.episode for e in events[1:]], [1, 2, 3, 4])
            self.assertEqual([e.status for e in events[1:]], [""] * 4)
            self.assertTrue(os.path.exists(run.result["policy_file"]))
            # Bad data is a ValueError naming the problem.
            with self.assertRaisesRegex(ValueError, "holds no shape file|no .brep"):
                AutoBlock.train(AutoBlock.TrainingRequest(os.path.join(folder, "bad.pt"), train_folder=folder,
                                                          test_folder=support.SAMPLES, episodes=2))
        finally:
            support.remove_folder(folder)

    def test_training_on_general_faces(self):
        """Issue 12: generated general faces and faces with arcs train the lookahead agent, whose policy then
        decomposes a general face; and the paper's agent, with its continuous angle; a policy of the paper's
        agent written before that (sac-faithful) refuses general faces with a ValueError."""
        folder = support.temporary_folder()
        try:
            output = os.path.join(folder, "general.pt")
            request = AutoBlock.TrainingRequest(output, train_generate={"count": 1, "general": 2, "arcs": 1, "seed": 4},
                                                test_generate={"count": 0, "general": 1, "seed": 5},
                                                episodes=4, eval_every=2, reward="mesh", seed=6)
            request.validate()
            events = []
            result = AutoBlock.train(request, events.append)
            # First a status event: the reference returns (the search on the general test faces).
            self.assertRegex(events[0].status, "the search on [1-9][0-9]* general ones")
            self.assertEqual(events[0].episode, 0)
            events = events[1:]
            self.assertFalse(result["cancelled"])
            self.assertEqual([e.episode for e in events], [1, 2, 3, 4])
            self.assertTrue(all(e.test_return is not None for e in events[1::2]))
            self.assertEqual(result["policy_file"], output)
            hexagon = Part.Face(Part.makePolygon([FreeCAD.Vector(*p) for p in
                                                  ((0, 0, 0), (6, 0, 0), (8, 3, 0), (5, 7, 0), (0, 6, 0), (-2, 3, 0),
                                                   (0, 0, 0))]))
            decomposition = AutoBlock.decompose(hexagon, policy=output)
            self.assertTrue(decomposition.complete)
            self.assertGreaterEqual(decomposition.n_blocks, 1)
            # Beside sac-mesh's network, as the network for general faces (the twin of autoblock combine): the
            # hexagon is decomposed as by the policy trained here, a rectilinear face as by sac-mesh.
            both = os.path.join(folder, "both.pt")
            meta = AutoBlock.combine_policies("sac-mesh", output, both)
            self.assertEqual(meta["version"], 2)
            self.assertEqual(meta["general"]["training"]["episodes"], 4)
            self.assertTrue(AutoBlock.policy_info(both)["general_network"])
            self.assertFalse(AutoBlock.policy_info(output)["general_network"])
            combined = AutoBlock.decompose(hexagon, policy=both)
            self.assertEqual([(c.local, c.direction) for c in combined.cuts],
                             [(c.local, c.direction) for c in decomposition.cuts])
            grid = support.read_face()
            self.assertEqual([repr(c) for c in AutoBlock.decompose(grid, policy=both).cuts],
                             [repr(c) for c in AutoBlock.decompose(grid, policy="sac-mesh").cuts])
            with self.assertRaisesRegex(ValueError, "different reward presets"):
                AutoBlock.combine_policies("sac-paper", output, os.path.join(folder, "x.pt"))
            self.assertFalse(os.path.exists(os.path.join(folder, "x.pt")))
            paper = AutoBlock.TrainingRequest(os.path.join(folder, "paper.pt"),
                                              train_generate={"count": 1, "general": 2, "seed": 4},
                                              test_generate={"count": 0, "general": 1, "seed": 5}, episodes=3,
                                              agent="paper", reward="mesh")
            paper.validate()
            self.assertFalse(AutoBlock.train(paper)["cancelled"])
            decomposition = AutoBlock.decompose(hexagon, policy=paper.output)
            self.assertTrue(decomposition.complete)
            self.assertGreaterEqual(decomposition.n_blocks, 1)
            with self.assertRaisesRegex(ValueError, "before"):
                AutoBlock.decompose(hexagon, policy="sac-faithful")
        finally:
            support.remove_folder(folder)

    def test_the_run_protocol(self):
        from AutoBlock import training

        gate = threading.Event()

        class CountingRun(training.TrainingRun):
            """Reports episodes until cancelled (the protocol's test double)."""

            def work(self, report, cancelled):
                for episode in range(1, 1000):
                    if not report({"episode": episode, "episodes": 999, "train_return": episode * 0.5}):
                        return {"cancelled": True, "checkpoint": self.request.checkpoint}
                    if episode == 3:
                        gate.set()
                    time.sleep(0.01)
                return {"cancelled": False}

        run = CountingRun(training.TrainingRequest("/tmp/p.pt", train_folder=support.SAMPLES,
                                                   test_folder=support.SAMPLES))
        run.start()
        self.assertTrue(gate.wait(10))
        run.cancel()
        run.wait(10)
        self.assertTrue(run.done)
        self.assertIsNone(run.error)
        self.assertTrue(run.result["cancelled"])
        events = run.poll()
        self.assertGreaterEqual(len(events), 3)
        self.assertEqual([e.episode for e in events[:3]], [1, 2, 3])
        self.assertEqual(events[2].train_return, 1.5)

        class FailingRun(training.TrainingRun):
            def work(self, report, cancelled):
                raise RuntimeError("out of memory")

        run = FailingRun(training.TrainingRequest("/tmp/p.pt", train_folder=support.SAMPLES))
        run.start()
        run.wait(10)
        self.assertIn("out of memory", run.error)


# The outward faces of a C3D8 hexahedron (src/core/mesh/hex_mesh.h; Abaqus S1..S6).
C3D8_FACES = ((0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7))


def c3d8_volume(corners):
    """The volume of a hexahedron with planar faces whose corners (8 FreeCAD.Vector) are in the C3D8 order, by
    the divergence theorem over its faces split into triangles: negative when the order turns it inside out."""
    volume = 0.0
    for a, b, c, d in C3D8_FACES:
        for p, q, r in ((corners[a], corners[b], corners[c]), (corners[a], corners[c], corners[d])):
            volume += p.dot(q.cross(r)) / 6.0
    return volume


def abaqus_elements(path):
    """{element number: [node numbers]} and {node number: FreeCAD.Vector} of an .inp file's C3D8 elements (as
    FreeCAD's FemMesh.writeABAQUS, used by its CalculiX tools, writes them)."""
    nodes, elements, section = {}, {}, None
    with open(path) as stream:
        for line in stream:
            line = line.strip()
            if not line or line.startswith("**"):
                continue
            if line.startswith("*"):
                keyword = line.split(",")[0].upper()
                section = "node" if keyword == "*NODE" else (
                    "hexa" if keyword == "*ELEMENT" and "C3D8" in line.upper() else None)
                continue
            values = [v for v in line.split(",") if v.strip()]
            if section == "node":
                nodes[int(values[0])] = FreeCAD.Vector(*[float(v) for v in values[1:4]])
            elif section == "hexa":
                elements[int(values[0])] = [int(v) for v in values[1:]]
    return elements, nodes


class TestSolids(unittest.TestCase):
    """Swept solids: hexahedral meshes through the console, the AutoBlock solid object and its hexa8 FEM mesh."""

    def setUp(self):
        self.doc = support.new_document("solids")
        self.folder = support.temporary_folder()

    def tearDown(self):
        support.close_document(self.doc)
        support.remove_folder(self.folder)

    def holed_extrusion(self, direction=FreeCAD.Vector(0, 0, 5)):
        """An L-shaped face with a square hole, extruded as a solid by Part's Extrusion (a Pad-like feature)."""
        V = FreeCAD.Vector
        outer = Part.makePolygon(support.l_points(width=8, height=6, notch=4) + [V(0, 0, 0)])
        hole = Part.makePolygon([V(1, 1, 0), V(2, 1, 0), V(2, 2, 0), V(1, 2, 0), V(1, 1, 0)])
        face = Part.makeFace([outer, hole], "Part::FaceMakerBullseye")
        profile = support.add_face(self.doc, face, "Profile")
        extrusion = self.doc.addObject("Part::Extrusion", "Extrusion")
        extrusion.Base = profile
        extrusion.DirMode = "Custom"
        extrusion.Dir = direction
        extrusion.LengthFwd = direction.Length
        extrusion.Solid = True
        self.doc.recompute()
        self.assertEqual(len(extrusion.Shape.Solids), 1)
        return extrusion

    def check_hexa8(self, femmesh, volume, hexes):
        """Every hexa8 of `femmesh`, as FreeCAD's own .inp writer gives it to CalculiX, has a positive C3D8 volume,
        and the volumes add up to the solid's."""
        self.assertEqual(femmesh.HexaCount, hexes)
        self.assertEqual(femmesh.VolumeCount, hexes)
        path = os.path.join(self.folder, "mesh.inp")
        femmesh.writeABAQUS(path, 1, False)
        elements, nodes = abaqus_elements(path)
        self.assertEqual(len(elements), hexes)
        volumes = [c3d8_volume([nodes[n] for n in element]) for element in elements.values()]
        self.assertGreater(min(volumes), 0.0)
        self.assertAlmostEqual(sum(volumes), volume, delta=1e-9 * volume)

    def test_a_plate_with_drilled_holes_meshes_to_hexahedra_with_nodes_on_the_holes(self):
        """Side faces that are cylinders along the sweep (drilled holes, a rounded end) are taken: the hexahedra's
        side nodes lie on the cylinders, and FreeCAD's own .inp of the mesh has positive C3D8 volumes."""
        V = FreeCAD.Vector
        plate = Part.makeBox(30, 12, 2)
        holes = [(V(7, 6, 0), 2.5), (V(20, 5, 0), 1.5)]
        for centre, r in holes:
            plate = plate.cut(Part.makeCylinder(r, 4, centre + V(0, 0, -1)))
        plate = plate.fuse(Part.makeCylinder(6, 2, V(30, 6, 0))).removeSplitter()  # a rounded end
        source = support.add_face(self.doc, plate, "Plate")
        self.assertTrue(AutoBlock.is_solid(source))
        mesh = AutoBlock.mesh(source, size=1.0)
        self.assertIsInstance(mesh, AutoBlock.HexMeshResult)
        self.assertTrue(mesh.conformal)
        for centre, r in holes:
            on = [p for p in mesh.nodes if abs(math.hypot(p.x - centre.x, p.y - centre.y) - r) < 1e-9 * r]
            self.assertGreaterEqual(len(on), 24 * (mesh.layers + 1))
            self.assertFalse([p for p in mesh.nodes if math.hypot(p.x - centre.x, p.y - centre.y) < r - 1e-9 * r])
        volumes = [c3d8_volume([mesh.nodes[i] for i in h]) for h in mesh.hexes]
        self.assertGreater(min(volumes), 0.0)
        # The chords across the holes and the rounded end: the volumes differ from the solid's a little.
        self.assertAlmostEqual(sum(volumes), plate.Volume, delta=0.01 * plate.Volume)
        obj = AutoBlock.make_autoblock_solid(source, mesh_size=1.0)
        self.assertAlmostEqual(sum(s.Volume for s in obj.Shape.Solids), plate.Volume, delta=1e-6 * plate.Volume)
        self.assertEqual(len(AutoBlock.hex_mesh_objects_of(obj)), 1)

    def test_a_pad_of_a_sketch_with_a_line_drawn_in_two_pieces(self):
        """A side drawn as two collinear lines (a vertex mid-edge) splits the solid's side face in two: the cap's
        mesh has a node at the vertex and the hexahedra a column of nodes up the split (the sweep failed its
        conformity check before); the face alone meshes with the node too."""
        V = FreeCAD.Vector
        points = [V(0, 0, 0), V(3.37, 0, 0), V(10, 0, 0), V(10, 4, 0), V(0, 4, 0), V(0, 0, 0)]
        face = Part.Face(Part.makePolygon(points))
        self.assertEqual(len(face.Vertexes), 5)
        solid = face.extrude(V(0, 0, 3))
        self.assertEqual(len(solid.Faces), 7)  # the side below the split is two faces
        source = support.add_face(self.doc, solid, "SplitPad")
        mesh = AutoBlock.mesh(source, size=1.0)
        self.assertIsInstance(mesh, AutoBlock.HexMeshResult)
        self.assertTrue(mesh.conformal)
        column = [p for p in mesh.nodes if abs(p.x - 3.37) < 1e-9 and abs(p.y) < 1e-9]
        self.assertEqual(len(column), mesh.layers + 1)
        flat = AutoBlock.mesh(support.add_face(self.doc, face, "SplitFace"), size=1.0)
        self.assertTrue(flat.conformal)
        self.assertTrue([p for p in flat.nodes if abs(p.x - 3.37) < 1e-9 and abs(p.y) < 1e-9])

    def test_boxes_fused_without_refining_mesh_with_layers_at_the_split(self):
        """Two boxes fused and not refined leave the sides split across the sweep: the layers meet the split
        (a ValueError before, an internal error before that), every side face gets its quads, and the same
        solid refined meshes to the same count; a split that slants is a ValueError with the remedy."""
        V = FreeCAD.Vector
        fused = Part.makeBox(10, 4, 1.3).fuse(Part.makeBox(10, 4, 1.7, V(0, 0, 1.3)))
        self.assertEqual(len(fused.Faces), 10)
        mesh = AutoBlock.mesh(support.add_face(self.doc, fused, "Stacked"), size=0.5)
        self.assertIsInstance(mesh, AutoBlock.HexMeshResult)
        self.assertTrue(mesh.conformal)
        self.assertAlmostEqual(mesh.volume, 120.0)
        heights = sorted({round(p.z, 9) for p in mesh.nodes})
        self.assertIn(1.3, heights)
        self.assertEqual(len(heights), mesh.layers + 1)
        refined = AutoBlock.mesh(support.add_face(self.doc, fused.removeSplitter(), "Refined"), size=0.5)
        self.assertTrue(refined.conformal)
        self.assertEqual((len(refined.hexes), refined.layers), (len(mesh.hexes), mesh.layers))
        lower = Part.Face(Part.makePolygon([V(0, 0, 0), V(10, 0, 0), V(10, 0, 2), V(0, 0, 1), V(0, 0, 0)])).extrude(V(0, 4, 0))
        upper = Part.Face(Part.makePolygon([V(0, 0, 1), V(10, 0, 2), V(10, 0, 3), V(0, 0, 3), V(0, 0, 1)])).extrude(V(0, 4, 0))
        slanted = support.add_face(self.doc, lower.fuse(upper), "Slanted")
        with self.assertRaisesRegex(ValueError, "is split across the sweep from face .* slants .* Refine shape"):
            AutoBlock.mesh(slanted, size=1.0)

    def test_boxes_fused_into_an_l_are_refused_with_the_remedy_and_mesh_refined(self):
        """Two boxes fused into an L without refining split the caps too: no pair of caps as it is, a
        ValueError that says merging the split faces makes it a sweep, and how; refined, it meshes."""
        fused = Part.makeBox(10, 4, 3).fuse(Part.makeBox(4, 6, 3, FreeCAD.Vector(0, 4, 0)))
        with self.assertRaisesRegex(ValueError, r"merging its faces that could be one \(11 faces into 8.*Refine shape"):
            AutoBlock.mesh(support.add_face(self.doc, fused, "FusedL"), size=1.0)
        mesh = AutoBlock.mesh(support.add_face(self.doc, fused.removeSplitter(), "RefinedL"), size=1.0)
        self.assertTrue(mesh.conformal)
        self.assertAlmostEqual(mesh.volume, 10 * 4 * 3 + 4 * 6 * 3)

    def test_a_fusion_that_is_a_sweep_once_refined_gets_a_refined_copy(self):
        """Part's Fusion leaves Refine off: two boxes fused into an L keep their caps split, so the fusion is no
        sweep as it is; refines_to_solid says it would be refined, refined_copy adds the Part::Refine feature
        (one undoable step) that meshes and follows the fusion."""
        V = FreeCAD.Vector
        fusion, long_box, short_box = support.add_l_fusion(self.doc)
        self.assertFalse(fusion.Refine)
        self.assertTrue(AutoBlock.is_solid(fusion))
        with self.assertRaisesRegex(ValueError, "merging its faces that could be one"):
            AutoBlock.check_solid(fusion)
        self.assertTrue(AutoBlock.refines_to_solid(fusion))
        self.assertFalse(AutoBlock.refines_to_solid(long_box))  # a sweep already
        boss = self.doc.addObject("Part::MultiFuse", "Boss")
        boss.Shapes = [self.doc.addObject("Part::Box", "Plate"), self.doc.addObject("Part::Box", "Knob")]
        boss.Shapes[1].Placement.Base = V(2, 2, 10)
        self.doc.recompute()
        self.assertFalse(AutoBlock.refines_to_solid(boss))  # no sweep, refined or not
        self.assertFalse(AutoBlock.refines_to_solid((fusion, "Face1")))  # a face
        undo_count = self.doc.UndoCount
        copy = AutoBlock.refined_copy(fusion)
        self.assertEqual(copy.TypeId, "Part::Refine")
        self.assertIs(copy.Source, fusion)
        self.assertEqual(self.doc.UndoCount, undo_count + 1)
        self.assertLess(len(copy.Shape.Faces), len(fusion.Shape.Faces))
        mesh = AutoBlock.mesh(copy, size=1.0)
        self.assertTrue(mesh.conformal)
        self.assertAlmostEqual(mesh.volume, 10 * 4 * 3 + 4 * 6 * 3)
        short_box.Width = 8  # the copy follows
        self.doc.recompute()
        self.assertAlmostEqual(AutoBlock.mesh(copy, size=1.0).volume, 10 * 4 * 3 + 4 * 8 * 3)
        with self.assertRaisesRegex(ValueError, "document object"):
            AutoBlock.refined_copy(fusion.Shape)

    def test_a_pad_on_a_pad_meshes_with_layers_at_the_step(self):
        """PartDesign's everyday way to a taller part: a second Pad of the same outline on the first's top,
        unrefined (Refine is off by default), so its sides are split at the first Pad's height: the body
        meshes with a layer of nodes there."""
        body, pad = add_rectangle_pad(self.doc)
        upper = body.newObject("PartDesign::Pad", "UpperPad")
        upper.Profile = add_rectangle_sketch(body, "UpperSketch", 5.0)
        upper.Length = 3.0
        upper.Refine = False
        self.doc.recompute()
        self.assertEqual(len(body.Shape.Faces), 10)  # four sides, each in two
        mesh = AutoBlock.mesh(body, size=2.0)
        self.assertIsInstance(mesh, AutoBlock.HexMeshResult)
        self.assertTrue(mesh.conformal)
        self.assertAlmostEqual(mesh.volume, 40 * 25 * 8)
        heights = sorted({round(p.z, 9) for p in mesh.nodes})
        self.assertIn(5.0, heights)
        self.assertEqual(len(heights), mesh.layers + 1)

    def test_a_box_meshes_to_hexahedra(self):
        box = self.doc.addObject("Part::Box", "Box")
        box.Length, box.Width, box.Height = 10, 4, 3
        box.Placement.Base = FreeCAD.Vector(5, 0, 0)
        self.doc.recompute()
        self.assertTrue(AutoBlock.is_solid(box))
        self.assertFalse(AutoBlock.is_solid((box, "Face6")))  # a face of it is a face
        mesh = AutoBlock.mesh(box, size=1.0)
        self.assertIsInstance(mesh, AutoBlock.HexMeshResult)
        self.assertEqual(len(mesh.hexes), 10 * 4 * 3)
        self.assertEqual(len(mesh.nodes), 11 * 5 * 4)
        self.assertEqual((mesh.n_blocks, mesh.layers), (1, 3))
        self.assertEqual(mesh.quality["min_scaled_jacobian"], 1.0)
        self.assertEqual(mesh.quality["irregular_edges"], 0)
        self.assertTrue(mesh.conformal)
        self.assertAlmostEqual(mesh.volume, 120.0)
        self.assertAlmostEqual(min(p.x for p in mesh.nodes), 5.0)  # global coordinates
        # The core's C3D8 order: every hexahedron positive, the volumes adding up.
        volumes = [c3d8_volume([mesh.nodes[i] for i in h]) for h in mesh.hexes]
        self.assertGreater(min(volumes), 0.0)
        self.assertAlmostEqual(sum(volumes), 120.0, places=9)
        self.check_hexa8(mesh.fem_mesh(), 120.0, 120)
        self.assertEqual(len(mesh.blocks), 1)
        self.assertAlmostEqual(mesh.blocks[0].Volume, 120.0)
        # layers and grading reach the core.
        graded = AutoBlock.mesh_solid(box, size=1.0, layers=6, grading=1.5)
        self.assertEqual((graded.layers, len(graded.hexes)), (6, 240))
        zs = sorted(set(round(p.z, 9) for p in graded.nodes))
        self.assertAlmostEqual((zs[2] - zs[1]) / (zs[1] - zs[0]), 1.5)

    def test_an_extrusion_with_a_hole_gets_prism_blocks_and_a_hexa8_mesh(self):
        from AutoBlock.objects.fem_mesh import is_autoblock_hex_mesh

        extrusion = self.holed_extrusion()
        solid = extrusion.Shape.Solids[0]
        expected = AutoBlock.mesh(extrusion, size=1.0)
        self.assertGreater(expected.n_blocks, 2)
        self.assertTrue(expected.conformal)
        self.assertEqual(expected.quality["min_scaled_jacobian"], 1.0)
        undo_count = self.doc.UndoCount
        obj = AutoBlock.make_autoblock_solid(extrusion, mesh_size=1.0)
        self.assertEqual(self.doc.UndoCount, undo_count + 1)  # object and mesh: one transaction
        self.assertEqual(self.doc.UndoNames[0], "Auto-Block")
        self.assertTrue(AutoBlock.is_autoblock_solid(obj))
        # The solid split into prism blocks sharing their faces.
        self.assertEqual(obj.NumberOfBlocks, expected.n_blocks)
        self.assertEqual(len(obj.Shape.Solids), obj.NumberOfBlocks)
        self.assertAlmostEqual(sum(s.Volume for s in obj.Shape.Solids), solid.Volume, delta=1e-9 * solid.Volume)
        self.assertLess(len(obj.Shape.Faces), sum(len(s.Faces) for s in obj.Shape.Solids))  # shared faces
        self.assertEqual(list(obj.Caps), list(expected.caps))
        # Its hexa8 FEM mesh.
        meshes = AutoBlock.hex_mesh_objects_of(obj)
        self.assertEqual(len(meshes), 1)
        mesh = meshes[0]
        self.assertTrue(is_autoblock_hex_mesh(mesh))
        self.assertEqual(mesh.TypeId, "Fem::FemMeshObjectPython")
        self.assertEqual(mesh.NumberOfHexahedra, len(expected.hexes))
        self.assertEqual(mesh.FemMesh.NodeCount, len(expected.nodes))
        self.assertIn("min scaled Jacobian 1, 0 irregular edges, conformal", mesh.Quality)
        self.check_hexa8(mesh.FemMesh, solid.Volume, len(expected.hexes))
        self.assertIs(AutoBlock.mesh(obj), mesh)  # the object's mesh, not a second one
        self.assertIs(AutoBlock.mesh(mesh), mesh)
        # The core's exporters (as `autoblock mesh SOLID --out`): .inp with C3D8 elements and a set per block.
        inp = os.path.join(self.folder, "solid.inp")
        exported = AutoBlock.export_mesh(mesh, inp)
        self.assertEqual(exported.file, inp)
        elements, nodes = abaqus_elements(inp)
        self.assertEqual(len(elements), len(expected.hexes))
        volumes = [c3d8_volume([nodes[n] for n in element]) for element in elements.values()]
        self.assertGreater(min(volumes), 0.0)
        self.assertAlmostEqual(sum(volumes), solid.Volume, delta=1e-9 * solid.Volume)
        with open(inp) as stream:
            self.assertEqual(stream.read().count("ELSET=BLOCK_"), expected.n_blocks)
        msh = expected.export(os.path.join(self.folder, "solid.msh"))
        with open(msh) as stream:
            self.assertIn("$MeshFormat\n4.1 0 8", stream.read())
        with self.assertRaisesRegex(ValueError, "expected a .msh, .vtu or .inp file"):
            expected.export(os.path.join(self.folder, "solid.stl"))
        self.assertFalse(os.path.exists(os.path.join(self.folder, "solid.stl")))
        # It follows its source on recompute.
        extrusion.LengthFwd = 10
        self.doc.recompute()
        self.assertIn("Up-to-date", mesh.State)
        self.assertEqual(mesh.NumberOfLayers, 10)
        self.assertEqual(mesh.NumberOfHexahedra, 2 * len(expected.hexes))
        self.check_hexa8(mesh.FemMesh, extrusion.Shape.Volume, 2 * len(expected.hexes))
        # Undo of the Auto-Block removes the mesh with its object.
        names = [o.Name for o in self.doc.Objects]
        AutoBlock.make_autoblock_solid(extrusion, mesh_size=2.0)
        self.assertEqual(len(self.doc.Objects), len(names) + 2)
        self.doc.undo()
        self.assertEqual([o.Name for o in self.doc.Objects], names)

    def test_an_oblique_extrusion_and_a_pad_in_a_body(self):
        oblique = self.holed_extrusion(FreeCAD.Vector(1, 0, 4))
        mesh = AutoBlock.mesh(oblique, size=1.0)
        self.assertTrue(mesh.conformal)
        self.assertAlmostEqual(mesh.quality["min_scaled_jacobian"], 4 / 17 ** 0.5, places=9)
        self.check_hexa8(mesh.fem_mesh(), oblique.Shape.Volume, len(mesh.hexes))
        body, pad = support.add_l_pad(self.doc)
        for source in (pad, body):
            obj = AutoBlock.make_autoblock_solid(source, mesh_size=0.5)
            hexa = AutoBlock.hex_mesh_objects_of(obj)[0]
            self.assertEqual(obj.NumberOfBlocks, 2)
            self.check_hexa8(hexa.FemMesh, pad.Shape.Volume, hexa.NumberOfHexahedra)

    def test_a_pad_given_directly_is_placed_by_its_body(self):
        body, pad = support.add_l_pad(self.doc)
        body.Placement = FreeCAD.Placement(FreeCAD.Vector(50, 0, 0), FreeCAD.Rotation(FreeCAD.Vector(0, 0, 1), 90))
        self.doc.recompute()
        placed = Part.getShape(body).BoundBox  # the Body's shape: its tip, the Pad, where the Body puts it
        self.assertAlmostEqual(placed.XMin, 46.0)
        self.assertAlmostEqual(pad.Shape.BoundBox.XMin, 0.0)  # the Pad's own shape is not moved
        obj = AutoBlock.make_autoblock_solid(pad, mesh_size=0.5)
        self.assertTrue(obj.Shape.BoundBox.isInside(placed) and placed.isInside(obj.Shape.BoundBox),
                        (obj.Shape.BoundBox, placed))
        self.assertAlmostEqual(obj.Shape.Volume, pad.Shape.Volume, places=9)
        hexa = AutoBlock.hex_mesh_objects_of(obj)[0]
        self.assertAlmostEqual(hexa.FemMesh.BoundBox.XMin, 46.0, places=9)
        self.assertEqual(list(obj.Containers), [body])
        # Moving the Body (the Pad itself does not change) recomputes the object and its mesh.
        body.Placement.Base = FreeCAD.Vector(-20, 0, 0)
        self.doc.recompute()
        self.assertAlmostEqual(obj.Shape.BoundBox.XMin, -24.0, places=9)
        self.assertAlmostEqual(hexa.FemMesh.BoundBox.XMin, -24.0, places=9)
        # The Body put into an App::Part: once recomputed, the object follows the App::Part too, and both
        # placements apply.
        part = self.doc.addObject("App::Part", "Part")
        part.addObject(body)
        self.doc.recompute()
        obj.touch()
        self.doc.recompute()
        self.assertEqual(list(obj.Containers), [body, part])
        part.Placement.Base = FreeCAD.Vector(0, 0, 10)
        self.doc.recompute()
        box = obj.Shape.BoundBox
        self.assertEqual([round(v, 9) for v in (box.XMin, box.XMax, box.YMin, box.YMax, box.ZMin, box.ZMax)],
                         [-24.0, -20.0, 0.0, 4.0, 10.0, 13.0])
        self.assertAlmostEqual(hexa.FemMesh.BoundBox.ZMin, 10.0, places=9)

    def test_a_cap_face_designates_its_solid(self):
        extrusion = self.holed_extrusion()
        caps = AutoBlock.check_solid(extrusion)["caps"]
        for number in range(1, len(extrusion.Shape.Faces) + 1):
            expected = extrusion if number in caps else None
            self.assertIs(AutoBlock.cap_solid(extrusion, "Face{}".format(number)), expected, number)
        self.assertIs(AutoBlock.cap_solid((extrusion, "Face{}".format(caps[1]))), extrusion)
        self.assertIsNone(AutoBlock.cap_solid(extrusion))  # no face named
        self.assertIsNone(AutoBlock.cap_solid(extrusion, "Edge1"))
        body, pad = support.add_l_pad(self.doc)
        pad_caps = AutoBlock.check_solid(pad)["caps"]
        self.assertIs(AutoBlock.cap_solid(body, "Pad.Face{}".format(pad_caps[0])), pad)
        side = next(n for n in range(1, 9) if n not in pad_caps)
        self.assertIsNone(AutoBlock.cap_solid(body, "Pad.Face{}".format(side)))
        cylinder = self.doc.addObject("Part::Cylinder", "Cylinder")  # a sweep of its end disk
        cone = self.doc.addObject("Part::Cone", "Cone")  # planar ends, but not a sweep AutoBlock takes
        self.doc.recompute()
        self.assertIs(AutoBlock.cap_solid(cylinder, "Face2"), cylinder)
        self.assertIsNone(AutoBlock.cap_solid(cylinder, "Face1"))  # its side
        self.assertIsNone(AutoBlock.cap_solid(cone, "Face2"))
        face = support.add_face(self.doc, support.read_face())
        self.assertIsNone(AutoBlock.cap_solid(face, "Face1"))  # a face alone
        # The console keeps making a face object when asked for a cap face; make_autoblock_solid takes a cap
        # (what Auto-Block echoes for a selected cap) and refuses a side face, leaving the document as it was.
        obj = AutoBlock.make_autoblock(extrusion, "Face{}".format(caps[0]))
        self.assertTrue(AutoBlock.is_autoblock(obj))
        self.assertFalse(AutoBlock.is_autoblock_solid(obj))
        names = [o.Name for o in self.doc.Objects]
        with self.assertRaisesRegex(ValueError, r"^Body\.Pad\.Face{} is not a cap face of a swept solid".format(side)):
            AutoBlock.make_autoblock_solid((body, "Pad.Face{}".format(side)))
        self.assertEqual([o.Name for o in self.doc.Objects], names)
        solid = AutoBlock.make_autoblock_solid((body, "Pad.Face{}".format(pad_caps[1])), mesh=False)
        self.assertIs(solid.Source, pad)

    def test_the_caps_cuts_step_on_the_cap(self):
        # A holed L in a tilted plane, swept along its normal: the cap's frame is not the model's.
        V = FreeCAD.Vector
        outer = Part.makePolygon(support.l_points(width=8, height=6, notch=4) + [V(0, 0, 0)])
        hole = Part.makePolygon([V(1, 1, 0), V(2, 1, 0), V(2, 2, 0), V(1, 2, 0), V(1, 1, 0)])
        face = Part.makeFace([outer, hole], "Part::FaceMakerBullseye")
        face.Placement = FreeCAD.Placement(V(3, -2, 7), FreeCAD.Rotation(V(1, 1, 0), 35))
        normal = face.normalAt(0, 0)
        source = support.add_face(self.doc, face.extrude(normal * 4), "Tilted")
        mesh = AutoBlock.mesh(source, size=1.0)
        cap = mesh.cap
        self.assertIsInstance(cap, AutoBlock.DecompositionResult)
        self.assertFalse(cap.frame.isIdentity())
        self.assertEqual(cap.n_blocks, mesh.n_blocks)
        self.assertGreaterEqual(len(cap.cuts), 2)
        self.assertEqual(cap.blocks, [])
        bottom = source.Shape.Faces[mesh.caps[0] - 1]
        stepper = mesh.stepper()
        self.assertEqual(stepper.steps, len(cap.cuts))
        last = stepper.step(stepper.steps)
        self.assertEqual(last.blocks, mesh.n_blocks)
        # The pieces lie on the bottom cap and cover it; the first cut's vertex is a corner of the cap.
        self.assertAlmostEqual(sum(p.face.Area for p in last.pieces), bottom.Area, places=9)
        for piece in last.pieces:
            for vertex in piece.face.Vertexes:
                self.assertLess(bottom.distToShape(vertex)[0], 1e-9)
        corner = stepper.step(0).next.vertex
        self.assertLess(min((corner - v.Point).Length for v in bottom.Vertexes), 1e-9)
        # The solid object keeps the cap's cuts; stepping through them needs it up to date.
        obj = AutoBlock.make_autoblock_solid(source, mesh_size=1.0)
        self.assertEqual(obj.NumberOfCuts, len(cap.cuts))
        self.assertAlmostEqual(obj.Return, cap.ret)
        self.assertEqual(obj.RewardUsed, cap.reward)
        stored = AutoBlock.stepper_of(obj)
        self.assertEqual(stored.cuts, stepper.cuts)
        self.assertEqual(stored.step(stored.steps).blocks, obj.NumberOfBlocks)
        self.assertAlmostEqual(sum(p.face.Area for p in stored.step(stored.steps).pieces), bottom.Area, places=9)
        source.Shape = source.Shape.copy().scale(2.0)  # another solid, not recomputed yet
        with self.assertRaisesRegex(ValueError, "out of date"):
            AutoBlock.stepper_of(obj)

    def test_save_and_reopen_keeps_the_hexahedral_mesh(self):
        extrusion = self.holed_extrusion()
        obj = AutoBlock.make_autoblock_solid(extrusion, mesh_size=1.0)
        mesh = AutoBlock.hex_mesh_objects_of(obj)[0]
        hexes, nodes, blocks = mesh.NumberOfHexahedra, mesh.FemMesh.NodeCount, obj.NumberOfBlocks
        names = (obj.Name, mesh.Name)
        path = os.path.join(self.folder, "solid.FCStd")
        self.doc.saveAs(path)
        support.close_document(self.doc)
        self.doc = FreeCAD.openDocument(path)
        obj, mesh = self.doc.getObject(names[0]), self.doc.getObject(names[1])
        self.assertTrue(AutoBlock.is_autoblock_solid(obj))
        self.assertEqual(AutoBlock.hex_mesh_objects_of(obj), [mesh])
        self.assertEqual(obj.NumberOfBlocks, blocks)
        self.assertEqual(len(obj.Shape.Solids), blocks)
        self.assertEqual((mesh.FemMesh.HexaCount, mesh.FemMesh.NodeCount), (hexes, nodes))
        self.check_hexa8(mesh.FemMesh, self.doc.getObject("Extrusion").Shape.Volume, hexes)
        # The cap's cuts step from the saved cut sequence, without a recompute.
        stepper = AutoBlock.stepper_of(obj)
        self.assertEqual(stepper.steps, obj.NumberOfCuts)
        self.assertEqual(stepper.step(stepper.steps).blocks, blocks)
        # And it recomputes after reopening.
        obj.MeshSize = 0.5
        self.doc.recompute()
        self.assertIn("Up-to-date", mesh.State)
        self.assertGreater(mesh.NumberOfHexahedra, 4 * hexes)

    def extruded_section(self, outer, hole, length, name):
        """A Part extrusion along +Z by `length` of the section bounded by `outer` and `hole` (corner lists)."""
        wire = lambda points: Part.makePolygon(points + points[:1])  # noqa: E731
        face = Part.makeFace([wire(outer), wire(hole)], "Part::FaceMakerBullseye")
        section = support.add_face(self.doc, face, name + "Section")
        bar = self.doc.addObject("Part::Extrusion", name)
        bar.Base = section
        bar.DirMode, bar.Dir, bar.LengthFwd, bar.Solid = "Custom", FreeCAD.Vector(0, 0, length), length, True
        self.doc.recompute()
        return bar, face

    def calculix(self, bar, mesh, supports, force, direction, end, inp_edit=None):
        """Solve with FreeCAD's FEM objects and CalculiX tools (femtools.ccxtools, ccx 2.20): steel (E 210000,
        nu 0.3), displacement constraints supports [(sub-element, axes held)], `force` on the face `end` along
        the edge `direction` (sub-element names of bar). inp_edit(text) -> text may change the .inp FreeCAD
        wrote before ccx runs. Returns {node number: displacement}."""
        import ObjectsFem
        from femtools import ccxtools

        analysis = ObjectsFem.makeAnalysis(self.doc, "Analysis")
        solver = ObjectsFem.makeSolverCalculixCcxTools(self.doc, "Solver")
        material = ObjectsFem.makeMaterialSolid(self.doc, "Steel")
        card = material.Material
        card.update({"Name": "Steel", "YoungsModulus": "210000 MPa", "PoissonRatio": "0.3", "Density": "7900 kg/m^3"})
        material.Material = card
        for member in (solver, material, mesh):
            analysis.addObject(member)
        for element, axes in supports:
            constraint = ObjectsFem.makeConstraintDisplacement(self.doc, "Support")
            constraint.References = [(bar, element)]
            for axis in axes:
                setattr(constraint, axis + "Free", False)
                setattr(constraint, axis + "Fix", True)
            analysis.addObject(constraint)
        load = ObjectsFem.makeConstraintForce(self.doc, "Force")
        load.References = [(bar, end)]
        load.Force = force
        load.Direction = (bar, [direction])
        load.Reversed = False
        analysis.addObject(load)
        self.doc.recompute()
        fea = ccxtools.FemToolsCcx(analysis, solver)
        fea.update_objects()
        work = os.path.join(self.folder, "ccx-" + bar.Name)
        os.makedirs(work)
        fea.setup_working_dir(work)
        fea.setup_ccx()
        self.assertEqual(fea.check_prerequisites(), "")
        fea.write_inp_file()
        if inp_edit is not None:
            with open(fea.inp_file_name) as stream:
                text = stream.read()
            with open(fea.inp_file_name, "w") as stream:
                stream.write(inp_edit(text))
        fea.ccx_run()
        fea.load_results()
        results = [o for o in analysis.Group if o.isDerivedFrom("Fem::FemResultObject")]
        self.assertEqual(len(results), 1)
        return dict(zip(results[0].NodeNumbers, results[0].DisplacementVectors))

    @staticmethod
    def number(elements, test):
        return next(i for i, e in enumerate(elements, 1) if test(e))

    def test_a_bar_in_tension_through_freecads_calculix_tools(self):
        # An L-section bar with a hole (area 17), length 20, meshed by AutoBlock and solved by CalculiX through
        # FreeCAD's tools. The fixed end only holds the axial displacement (plus two corners against rigid
        # motion), so the bar is free to contract: the stress is uniform and the end moves by F L / (E A), which
        # hexahedra represent exactly.
        V = FreeCAD.Vector
        length, force = 20.0, 1000.0
        bar, face = self.extruded_section([V(0, 0, 0), V(6, 0, 0), V(6, 2, 0), V(2, 2, 0), V(2, 5, 0), V(0, 5, 0)],
                                          [V(0.5, 0.5, 0), V(1.5, 0.5, 0), V(1.5, 1.5, 0), V(0.5, 1.5, 0)], length,
                                          "Bar")
        self.assertAlmostEqual(face.Area, 17.0)
        solid = bar.Shape
        mesh = AutoBlock.hex_mesh_objects_of(AutoBlock.make_autoblock_solid(bar, mesh_size=0.5))[0]
        vertex = lambda p: "Vertex{}".format(self.number(solid.Vertexes, lambda v: (v.Point - p).Length < 1e-9))  # noqa
        supports = [("Face{}".format(self.number(solid.Faces, lambda f: f.BoundBox.ZMax < 1e-9)), "z"),
                    (vertex(V(0, 0, 0)), "xy"), (vertex(V(6, 0, 0)), "y")]
        end = "Face{}".format(self.number(solid.Faces, lambda f: f.BoundBox.ZMin > length - 1e-9))
        axis = "Edge{}".format(self.number(solid.Edges, lambda e: e.BoundBox.ZLength > length - 1e-9))
        displacement = self.calculix(bar, mesh, supports, force, axis, end)
        ends = [displacement[n].z for n, p in mesh.FemMesh.Nodes.items() if abs(p.z - length) < 1e-9]
        self.assertGreater(len(ends), 20)
        theory = force * length / (210000.0 * face.Area)
        mean = sum(ends) / len(ends)
        self.assertLess(abs(mean / theory - 1.0), 0.005, "mean end displacement {} vs F L / (E A) = {}".format(
            mean, theory))

    def test_a_cantilever_through_freecads_calculix_tools(self):
        # A square tube (4 x 4, hole 2 x 2, length 40) clamped at one end, a force of 100 across the other end
        # face; AutoBlock's hexahedra at size 1. FreeCAD 0.20 writes hexa8 as C3D8 (full integration, which
        # stiffens in bending); the same .inp with C3D8I (incompatible modes, no locking) is solved too.
        # Beam theory: F L^3 / (3 E I), I = (4^4 - 2^4) / 12 = 20.
        V = FreeCAD.Vector
        length, force = 40.0, 100.0
        tips = {}
        for element in ("C3D8", "C3D8I"):
            tube, face = self.extruded_section([V(0, 0, 0), V(4, 0, 0), V(4, 4, 0), V(0, 4, 0)],
                                               [V(1, 1, 0), V(3, 1, 0), V(3, 3, 0), V(1, 3, 0)], length, "Tube" + element)
            solid = tube.Shape
            mesh = AutoBlock.hex_mesh_objects_of(AutoBlock.make_autoblock_solid(tube, mesh_size=1.0))[0]
            clamped = "Face{}".format(self.number(solid.Faces, lambda f: f.BoundBox.ZMax < 1e-9))
            end = "Face{}".format(self.number(solid.Faces, lambda f: f.BoundBox.ZMin > length - 1e-9))
            across = "Edge{}".format(self.number(solid.Edges, lambda e: e.BoundBox.XLength > 3.9 and e.BoundBox.ZMax < 1e-9))
            edit = (lambda text: text.replace("TYPE=C3D8,", "TYPE=C3D8I,")) if element == "C3D8I" else None
            displacement = self.calculix(tube, mesh, [(clamped, "xyz")], force, across, end, edit)
            ends = [displacement[n].x for n, p in mesh.FemMesh.Nodes.items() if abs(p.z - length) < 1e-9]
            tips[element] = sum(ends) / len(ends)
        theory = force * length ** 3 / (3 * 210000.0 * 20.0)
        for element, tip in tips.items():
            self.assertLess(abs(tip / theory - 1.0), 0.05, "{}: tip deflection {} vs F L^3 / (3 E I) = {}".format(
                element, tip, theory))
        self.assertGreater(tips["C3D8I"], tips["C3D8"])  # the incompatible modes do not lock
        print("AutoBlock cantilever: C3D8 {:.4f}, C3D8I {:.4f}, theory {:.4f}".format(
            tips["C3D8"], tips["C3D8I"], theory))

    def test_write_back_of_the_prism_blocks(self):
        extrusion = self.holed_extrusion()
        solid = extrusion.Shape.copy()
        holder = support.add_face(self.doc, solid, "Imported")  # a plain Part feature holding the solid
        obj = AutoBlock.make_autoblock_solid(holder, mesh_size=1.0)
        blocks = obj.NumberOfBlocks
        new = AutoBlock.write_back(obj, "new")
        self.assertEqual(len(new.Shape.Solids), blocks)
        self.assertAlmostEqual(new.Shape.Volume, solid.Volume, delta=1e-9 * solid.Volume)
        # A parametric source cannot be replaced; a plain Part feature can.
        parametric = AutoBlock.make_autoblock_solid(extrusion, mesh=False)
        with self.assertRaisesRegex(ValueError, "recomputed from its own inputs"):
            AutoBlock.write_back(parametric, "replace")
        mesh = AutoBlock.hex_mesh_objects_of(obj)[0].Name
        self.assertIs(AutoBlock.write_back(obj, "replace"), holder)
        self.assertEqual(len(holder.Shape.Solids), blocks)
        self.assertTrue(holder.Shape.isValid())
        self.assertAlmostEqual(holder.Shape.Volume, solid.Volume, delta=1e-9 * solid.Volume)
        self.assertIsNone(self.doc.getObject(mesh))  # the solid object and its mesh are gone
        self.assertFalse([o for o in self.doc.Objects if AutoBlock.is_autoblock_solid(o) and o.Source == holder])

    def test_a_solid_that_is_not_a_sweep_raises_value_error(self):
        sphere = self.doc.addObject("Part::Sphere", "Sphere")
        cone = self.doc.addObject("Part::Cone", "Cone")
        self.doc.recompute()
        names = [o.Name for o in self.doc.Objects]
        for source in (sphere, cone):
            with self.assertRaisesRegex(ValueError, r"^{}: face \d+ is curved \(a {}\): a swept solid's faces are planar, "
                                                    r"or cylinders along the sweep$".format(source.Label, source.Label.lower())):
                AutoBlock.mesh(source)
            with self.assertRaisesRegex(ValueError, "is curved"):
                AutoBlock.make_autoblock_solid(source)
        with self.assertRaisesRegex(ValueError, "is curved"):
            AutoBlock.mesh_solid(Part.makeCone(2, 1, 5))
        two = Part.makeCompound([Part.makeBox(1, 1, 1), Part.makeBox(1, 1, 1, FreeCAD.Vector(3, 0, 0))])
        with self.assertRaisesRegex(ValueError, "solid"):
            AutoBlock.mesh(two)
        with self.assertRaisesRegex(ValueError, "not a solid"):
            AutoBlock.mesh_solid(Part.makePlane(1, 1))
        self.assertEqual([o.Name for o in self.doc.Objects], names)


if __name__ == "__main__":
    unittest.main()

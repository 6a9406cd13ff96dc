"""App tests of the AutoBlock workbench, headless: freecadcmd -t TestAutoBlockApp (see run_freecad_tests.sh).

Console API, the parametric object (recompute when the source changes, undo, save and reopen),
write-back, bad faces, stepping, FEM mesh objects, the training protocol.
"""

import json
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
        self.assertIn(module.default_policy(), AutoBlock.policy_names())
        self.assertIn("optimal", AutoBlock.policy_names())
        self.assertEqual(AutoBlock.reward_presets(), ["paper"])
        self.assertEqual(set(AutoBlock.capabilities()), {"learned_policies", "training", "vertex_scores", "meshing"})

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
        self.assertEqual(result.policy, "optimal")
        self.assertTrue(result.complete)
        self.check_partition(result, face)
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
            triangle = Part.Face(Part.makePolygon([V(0, 0, 0), V(4, 0, 0), V(0, 3, 0), V(0, 0, 0)]))
            disc = Part.Face(Part.Wire(Part.makeCircle(2.0)))
            cases = [
                (sphere, "not planar"),
                (box, "6 faces"),
                ((box, "Edge1"), "not a face"),
                (triangle, "not parallel"),
                (disc, "only straight edges"),
                (Part.makeCompound([support.l_face(), support.l_face().translate(V(10, 0, 0))]), "2 faces"),
                (Part.makePolygon([V(0, 0, 0), V(1, 0, 0), V(1, 1, 0)]), "not all of its"),
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
        stepper = result.stepper()
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
                self.assertIsNone(view.next.scores)
                self.assertIn("learned policy", view.next.scores_note)
                running += cut.reward
            else:
                self.assertIsNone(view.next)
                self.assertEqual(view.blocks, result.n_blocks)
                self.assertEqual(sorted(p.index for p in view.pieces), list(range(result.n_blocks)))


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
            self.assertIn("sphere.step: skipped: ", lines[2])
            with open(os.path.join(out, "summary.json")) as f:
                summary = json.load(f)
            self.assertEqual([entry["file"] for entry in summary], names)
            for entry in summary:
                blocks = Part.read(os.path.join(out, entry["file"].replace(".brep", "-blocks.brep")))
                self.assertEqual(len(blocks.Faces), entry["n_blocks"])
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
        self.assertEqual(obj.Policy, "optimal")
        self.assertEqual(obj.RewardPreset, "paper")
        self.assertEqual(obj.getEnumerationsOfProperty("Policy"), AutoBlock.policy_names())
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
        obj = AutoBlock.make_autoblock(source)
        optimal = obj.Return
        obj.Policy = "random"
        obj.Seed = 5
        self.doc.recompute()
        self.assertEqual(obj.Status.split(":")[0], "random")
        self.assertLessEqual(obj.Return, optimal + 1e-9)

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
        if not AutoBlock.capabilities()["learned_policies"]:
            # Fails in the object's recompute, after it was added: it is removed again.
            with self.assertRaisesRegex(ValueError, "no learned policies"):
                AutoBlock.make_autoblock(source, policy="/tmp/my-policy.pt")
        self.assertEqual([o.Name for o in self.doc.Objects], names)
        self.assertEqual(self.doc.UndoCount, undo_count)
        self.assertIsNone(FreeCAD.getActiveTransaction())
        # Without undo (freecadcmd's default) as well.
        plain = support.new_document("plain", undo=False)
        try:
            source = support.add_face(plain, support.l_face())
            with self.assertRaises(ValueError):
                AutoBlock.make_autoblock(source, policy="/tmp/my-policy.pt")
            self.assertEqual([o.Name for o in plain.Objects], [source.Name])
        finally:
            support.close_document(plain)

    def test_save_and_reopen(self):
        source = support.add_face(self.doc, support.read_face())
        sketch_placement = FreeCAD.Placement(FreeCAD.Vector(0, 0, 0), FreeCAD.Rotation(FreeCAD.Vector(0, 1, 0), 90))
        sketch = support.add_l_sketch(self.doc, sketch_placement)
        obj = AutoBlock.make_autoblock(source, policy="greedy")
        side = AutoBlock.make_autoblock(sketch)
        blocks, ret, area = obj.NumberOfBlocks, obj.Return, obj.Shape.Area
        path = os.path.join(self.folder, "autoblock.FCStd")
        self.doc.saveAs(path)
        names = (obj.Name, side.Name, source.Name, sketch.Name)
        FreeCAD.closeDocument(self.doc.Name)
        self.doc = FreeCAD.openDocument(path)
        obj, side, source, sketch = (self.doc.getObject(n) for n in names)
        self.assertTrue(AutoBlock.is_autoblock(obj))
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
        # And saves again.
        self.doc.save()
        self.assertTrue(os.path.getsize(path) > 0)

    def test_write_back_as_a_new_part_feature(self):
        source = support.add_face(self.doc, support.read_face())
        obj = AutoBlock.make_autoblock(source)
        feature = AutoBlock.write_back(obj, "new")
        name = feature.Name
        self.assertEqual(feature.TypeId, "Part::Feature")
        self.assertEqual(len(feature.Shape.Faces), obj.NumberOfBlocks)
        self.assertAlmostEqual(feature.Shape.Area, obj.Shape.Area)
        self.assertEqual(self.doc.UndoNames[0], "Write back blocks")
        self.doc.undo()
        self.assertIsNone(self.doc.getObject(name))
        with self.assertRaisesRegex(ValueError, "'new' or 'replace'"):
            AutoBlock.write_back(obj, "sideways")

    def test_write_back_replacing_the_source(self):
        # A plain face: its shape becomes the blocks; the AutoBlock object has done its job.
        source = support.add_face(self.doc, support.read_face())
        source.Placement.Base = FreeCAD.Vector(0, 0, 3)
        obj = AutoBlock.make_autoblock(source)
        n, name = obj.NumberOfBlocks, obj.Name
        result = AutoBlock.write_back(obj, "replace")
        self.assertIs(result, source)
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

    def test_meshing_says_plainly_when_the_core_cannot(self):
        if AutoBlock.capabilities()["meshing"]:
            self.skipTest("this build can mesh")
        with self.assertRaisesRegex(NotImplementedError, "no quad mesher"):
            AutoBlock.mesh(None)


class TestTraining(unittest.TestCase):
    def test_requests_are_checked(self):
        folder = support.temporary_folder()
        try:
            good = AutoBlock.TrainingRequest(os.path.join(folder, "p.pt"), train_folder=support.SAMPLES)
            good.validate()
            generated = AutoBlock.TrainingRequest(os.path.join(folder, "p.pt"),
                                                  train_generate={"count": 5, "min_rects": 2, "max_rects": 4})
            generated.validate()
            self.assertEqual(generated.to_options()["train_generate"]["count"], 5)
            cases = [
                (AutoBlock.TrainingRequest(os.path.join(folder, "p.pt")), "no training data"),
                (AutoBlock.TrainingRequest("/no/such/dir/p.pt", train_folder=support.SAMPLES), "does not exist"),
                (AutoBlock.TrainingRequest(os.path.join(folder, "p.pt"), train_folder="/no/such"), "no such folder"),
                (AutoBlock.TrainingRequest(os.path.join(folder, "p.pt"), train_folder=support.SAMPLES, episodes=0),
                 "at least 1"),
                (AutoBlock.TrainingRequest(os.path.join(folder, "p.pt"), train_folder=support.SAMPLES, resume=True),
                 "nothing to resume"),
            ]
            for request, words in cases:
                with self.subTest(words=words):
                    with self.assertRaisesRegex(ValueError, words):
                        request.validate()
        finally:
            support.remove_folder(folder)

    def test_training_says_plainly_when_the_core_cannot(self):
        if AutoBlock.capabilities()["training"]:
            self.skipTest("this build can train")
        from AutoBlock import training

        self.assertIsNone(training.training_backend())
        with self.assertRaisesRegex(NotImplementedError, "not in this build"):
            AutoBlock.train(AutoBlock.TrainingRequest("/tmp/p.pt", train_folder=support.SAMPLES))

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

        run = CountingRun(training.TrainingRequest("/tmp/p.pt", train_folder=support.SAMPLES))
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


if __name__ == "__main__":
    unittest.main()

"""The Python module (python/, docs/python.md) against values worked out by
hand: the shading formula at a pixel centre, the exposure and sRGB curve,
ray counts, a ray tree's terms, edits, errors, files, Ctrl-C and the GIL.

Run by ctest as `python_test` (python/CMakeLists.txt), or by hand:
    PYTHONPATH=build/python /usr/bin/python3 -m unittest -v test_prism   (in python/tests)
"""

import os
import queue
import signal
import struct
import sys
import tempfile
import threading
import unittest
import zlib

import numpy as np

import prism

# A wall of C = (1, 0.5, 0.25), kdr = 0.5, at z = 0 facing the eye at
# (0, 0, 5); ambient 0.2; one light of 4 at the eye. The centre pixel of an
# odd-sized picture sees the wall's point (0, 0, 0) head on: N.L = 1, r = 5,
# so its radiance is C kdr (I_a + I / r^2) = C 0.5 (0.2 + 0.16) = C 0.18.
# (The same scene as tests/api_test.cpp.)
WALL = """resolution 5 5
ambient 0.2 0.2 0.2
light 0 0 5  4 4 4
surface 1 0.5 0.25  0.5 0 0  1 1
polygon 4  -10 -10 0  10 -10 0  10 10 0  -10 10 0
"""

# The wall half a mirror (ksr 0.5, exponent 1) before a background of
# (0.1, 0.2, 0.3). At the centre, N.H = 1: the highlight is
# ksr I (N.H)^e / r^2 = 0.5 * 4 / 25 = 0.08 per channel; the reflected ray
# leaves along +z and meets nothing: ksr * background = (0.05, 0.1, 0.15).
# Radiance: (0.18, 0.09, 0.045) + 0.08 + (0.05, 0.1, 0.15) = (0.31, 0.27, 0.275).
MIRROR_WALL = """resolution 5 5
background 0.1 0.2 0.3
ambient 0.2 0.2 0.2
light 0 0 5  4 4 4
surface 1 0.5 0.25  0.5 0.5 0  1 1
polygon 4  -10 -10 0  10 -10 0  10 10 0  -10 10 0
"""

C = np.array([1.0, 0.5, 0.25])


def centre(img):
    return img[img.shape[0] // 2, img.shape[1] // 2]


def srgb_encode(x):
    """The sRGB transfer function (IEC 61966-2-1) of a value in [0, 1]."""
    return np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.power(x, 1 / 2.4) - 0.055)


def read_tiff_rgb8(path):
    """The pixels of an 8-bit RGB TIFF, in strips, uncompressed or deflated,
    with or without the horizontal predictor: as (height, width, 3) uint8.
    Just enough TIFF (baseline tags 256, 257, 259, 273, 277, 279, 317) to
    read Prism's files without Prism."""
    with open(path, "rb") as f:
        data = f.read()
    order = {b"II": "<", b"MM": ">"}[data[:2]]
    (magic, ifd) = struct.unpack(order + "HI", data[2:8])
    assert magic == 42
    (count,) = struct.unpack(order + "H", data[ifd:ifd + 2])
    tags = {}
    for i in range(count):
        tag, kind, n, value = struct.unpack(order + "HHI4s", data[ifd + 2 + 12 * i:ifd + 14 + 12 * i])
        fmt = {3: "H", 4: "I"}.get(kind)
        if fmt is None:
            continue
        size = struct.calcsize(fmt) * n
        raw = value[:size] if size <= 4 else data[struct.unpack(order + "I", value)[0]:][:size]
        tags[tag] = struct.unpack(order + fmt * n, raw)
    width, height = tags[256][0], tags[257][0]
    assert tags[277][0] == 3
    compression = tags.get(259, (1,))[0]
    pixels = b""
    for offset, length in zip(tags[273], tags[279]):
        strip = data[offset:offset + length]
        pixels += zlib.decompress(strip) if compression in (8, 32946) else strip
    rgb = np.frombuffer(pixels, np.uint8)[:width * height * 3].reshape(height, width, 3)
    if tags.get(317, (1,))[0] == 2:  # horizontal differencing
        rgb = np.cumsum(rgb, axis=1, dtype=np.uint8)
    return rgb


class RenderTest(unittest.TestCase):
    def test_the_centre_pixel_is_the_shading_formula(self):
        scene = prism.parse(WALL)
        self.assertEqual((scene.width, scene.height), (5, 5))
        img = prism.render(scene, antialias=False)
        self.assertIsInstance(img, prism.Image)
        self.assertIsInstance(img, np.ndarray)
        self.assertEqual(img.shape, (5, 5, 3))
        self.assertEqual(img.dtype, np.float32)
        np.testing.assert_allclose(centre(img), C * 0.18, rtol=1e-6)
        # Every pixel sees the wall lit, nearer the centre brighter.
        self.assertTrue(np.all(img > 0))
        self.assertEqual(int(np.argmax(img[..., 0])), 12)

    def test_a_size_other_than_the_scenes(self):
        img = prism.render(prism.parse(WALL), width=7, height=3, antialias=False, threads=1)
        self.assertEqual(img.shape, (3, 7, 3))
        np.testing.assert_allclose(centre(img), C * 0.18, rtol=1e-6)

    def test_avgmax_is_the_mean_of_the_pixel_centres_max_channel(self):
        # Without antialiasing the picture holds the pixel centres only.
        img = prism.render(prism.parse(WALL), antialias=False)
        self.assertAlmostEqual(img.avgmax, float(np.mean(np.max(img.astype(np.float64), axis=2))),
                               places=6)

    def test_statistics_count_the_rays(self):
        img = prism.render(prism.parse(WALL, name="wall.sc"), antialias=False, depth=3, threads=1)
        stats = img.stats
        # The keys of `prism render --stats-json` (core/render/stats.cpp,
        # docs/statistics.md), for one process.
        self.assertEqual(set(stats), {
            "scene", "machine", "width", "height", "pixels", "max_depth", "thresh", "jitter",
            "no_aa", "bailout", "accel", "threads", "primitives", "load_seconds",
            "build_seconds", "cpu_seconds", "wall_seconds", "rays", "tir_events",
            "bailout_skipped", "rays_per_pixel", "supersampled_pixels", "supersampled_share",
            "avgmax"})
        self.assertEqual(set(stats["rays"]), {"eye", "eye_pass1", "eye_antialias", "shadow",
                                              "reflected", "transmitted", "bailout_pilot",
                                              "total"})
        self.assertEqual(stats["scene"], "wall.sc")
        # 5 x 5 pixel centres, each on the wall, one light: one shadow ray each.
        self.assertEqual(stats["rays"]["eye"], 25)
        self.assertEqual(stats["rays"]["eye_antialias"], 0)
        self.assertEqual(stats["rays"]["shadow"], 25)
        self.assertEqual(stats["rays"]["reflected"], 0)
        self.assertEqual(stats["rays"]["total"], 50)
        self.assertEqual(stats["rays_per_pixel"], 2.0)
        self.assertEqual((stats["width"], stats["height"], stats["pixels"]), (5, 5, 25))
        self.assertEqual(stats["max_depth"], 3)
        self.assertEqual(stats["threads"], 1)
        self.assertTrue(stats["no_aa"])
        self.assertEqual(stats["primitives"], 1)
        self.assertEqual(stats["avgmax"], img.avgmax)

    def test_supersampled_marks_the_pixels_of_pass_2(self):
        scene = prism.parse(WALL)
        self.assertFalse(prism.render(scene, antialias=False).supersampled.any())
        # At thresh 0 every pixel differing at all from a neighbour is
        # supersampled: on the wall each has a neighbour nearer to or farther
        # from the centre, so all 25.
        img = prism.render(scene, thresh=0.0)
        self.assertEqual(img.supersampled.shape, (5, 5))
        self.assertTrue(img.supersampled.all())
        self.assertEqual(img.stats["supersampled_pixels"], 25)

    def test_threads_zero_means_every_core(self):
        img = prism.render(prism.parse(WALL), antialias=False, threads=0)
        self.assertEqual(img.stats["threads"], len(os.sched_getaffinity(0)))

    def test_the_mirror_adds_its_highlight_and_the_background(self):
        img = prism.render(prism.parse(MIRROR_WALL), antialias=False)
        np.testing.assert_allclose(centre(img), [0.31, 0.27, 0.275], rtol=1e-6)
        # Depth 1: no reflected ray, the highlight stays.
        img = prism.render(prism.parse(MIRROR_WALL), antialias=False, depth=1)
        np.testing.assert_allclose(centre(img), [0.26, 0.17, 0.125], rtol=1e-6)

    def test_options_out_of_range_are_value_errors_naming_them(self):
        scene = prism.parse(WALL)
        for options, word in [({"depth": 0}, "depth"), ({"thresh": 1.5}, "thresh"),
                              ({"width": 10}, "width"), ({"bailout": -1.0}, "bailout"),
                              ({"threads": -1}, "threads")]:
            with self.subTest(options=options):
                with self.assertRaisesRegex(ValueError, word):
                    prism.render(scene, **options)


class ExposeTest(unittest.TestCase):
    def setUp(self):
        self.img = prism.render(prism.parse(WALL), antialias=False)

    def test_the_automatic_exposure_is_128_over_avgmax(self):
        rgb8 = prism.expose(self.img)
        self.assertEqual(rgb8.dtype, np.uint8)
        self.assertEqual(rgb8.shape, (5, 5, 3))
        expected = np.minimum(255, np.round(self.img.astype(np.float64) * 128 / self.img.avgmax))
        np.testing.assert_array_equal(rgb8, expected)

    def test_a_given_avgmax_overrides_the_renders(self):
        # Exposed as if avgmax were 0.18, the centre's max channel is 128; the
        # others scale with it.
        self.assertEqual(list(centre(prism.expose(self.img, avgmax=0.18))), [128, 64, 32])

    def test_srgb_encodes_after_exposure(self):
        rgb8 = prism.expose(self.img, srgb=True, avgmax=0.18)
        # sRGB of 128/255 = 0.50196: 1.055 * 0.50196^(1/2.4) - 0.055 = 0.73536 -> 188.
        self.assertEqual(centre(rgb8)[0], 188)
        linear = np.minimum(1.0, self.img.astype(np.float64) * 128 / 0.18 / 255)
        np.testing.assert_array_equal(rgb8, np.round(255 * srgb_encode(linear)))

    def test_a_plain_array_needs_its_avgmax(self):
        plain = np.asarray(self.img) * 2.0
        self.assertNotIsInstance(plain, prism.Image)
        with self.assertRaisesRegex(ValueError, "avgmax"):
            prism.expose(plain)
        # Twice the radiance at twice the avgmax: the same picture.
        np.testing.assert_array_equal(prism.expose(plain, avgmax=2 * self.img.avgmax),
                                      prism.expose(self.img))
        # Arithmetic on an Image gives new radiance, not the render's.
        self.assertNotIsInstance(self.img * 2, prism.Image)
        with self.assertRaises(ValueError):
            prism.expose(self.img * 2)

    def test_a_slice_keeps_the_renders_exposure(self):
        top = self.img[:2]
        self.assertIsInstance(top, prism.Image)
        self.assertEqual(top.avgmax, self.img.avgmax)
        np.testing.assert_array_equal(prism.expose(top), prism.expose(self.img)[:2])

    def test_a_picture_of_another_shape_is_refused(self):
        with self.assertRaisesRegex(ValueError, "shape"):
            prism.expose(np.zeros((4, 4)), avgmax=1.0)


class WriteTest(unittest.TestCase):
    def setUp(self):
        self.img = prism.render(prism.parse(WALL), antialias=False)
        self.dir = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.dir.cleanup()

    def test_the_tiff_holds_the_exposed_picture(self):
        path = os.path.join(self.dir.name, "wall.tif")
        prism.write(path, self.img)
        np.testing.assert_array_equal(read_tiff_rgb8(path), prism.expose(self.img))
        prism.write(path, self.img, srgb=True)
        np.testing.assert_array_equal(read_tiff_rgb8(path), prism.expose(self.img, srgb=True))

    def test_exr_keeps_float_radiance(self):
        # Written by the OpenImageIO module, found beside the extension.
        path = os.path.join(self.dir.name, "wall.exr")
        prism.write(path, self.img)
        with open(path, "rb") as f:
            self.assertEqual(f.read(4), b"\x76\x2f\x31\x01")  # OpenEXR's magic number

    def test_an_unwritable_file_is_a_runtime_error_naming_it(self):
        path = os.path.join(self.dir.name, "no-such-folder", "wall.tif")
        with self.assertRaisesRegex(RuntimeError, "no-such-folder"):
            prism.write(path, self.img)
        self.assertFalse(os.path.exists(os.path.dirname(path)))


class RayTreeTest(unittest.TestCase):
    def test_the_centre_rays_terms(self):
        tree = prism.ray_tree(prism.parse(WALL), 2, 2)
        self.assertEqual(tree["kind"], "eye")
        self.assertEqual(tree["depth"], 1)
        self.assertTrue(tree["hit"])
        np.testing.assert_allclose(tree["origin"], (0, 0, 5), atol=1e-12)
        np.testing.assert_allclose(tree["direction"], (0, 0, -1), atol=1e-12)
        np.testing.assert_allclose(tree["point"], (0, 0, 0), atol=1e-12)
        np.testing.assert_allclose(tree["normal"], (0, 0, 1), atol=1e-12)
        self.assertAlmostEqual(tree["t"], 5.0, places=12)
        self.assertEqual(tree["material"], {"color": (1.0, 0.5, 0.25), "kdr": 0.5, "ksr": 0.0,
                                            "kst": 0.0, "exponent": 1.0, "index": 1.0})
        self.assertEqual(len(tree["lights"]), 1)
        light = tree["lights"][0]
        self.assertEqual(light["light"], 1)
        self.assertAlmostEqual(light["distance"], 5.0, places=12)
        self.assertAlmostEqual(light["cosine"], 1.0, places=12)
        self.assertFalse(light["shadowed"])
        self.assertFalse(light["behind"])
        np.testing.assert_allclose(light["diffuse"], (0.16, 0.16, 0.16), rtol=1e-12)  # 4 * 1 / 25
        np.testing.assert_allclose(tree["ambient_diffuse"], C * 0.18, rtol=1e-12)
        np.testing.assert_allclose(tree["radiance"], C * 0.18, rtol=1e-12)
        self.assertEqual(tree["children"], [])  # ksr = kst = 0: nothing spawned

    def test_the_mirrors_reflected_ray_is_a_child(self):
        tree = prism.ray_tree(prism.parse(MIRROR_WALL), 2, 2)
        np.testing.assert_allclose(tree["highlight"], (0.08, 0.08, 0.08), rtol=1e-12)
        np.testing.assert_allclose(tree["reflected"], (0.05, 0.1, 0.15), rtol=1e-12)
        np.testing.assert_allclose(tree["radiance"], (0.31, 0.27, 0.275), rtol=1e-12)
        self.assertEqual(len(tree["children"]), 1)
        child = tree["children"][0]
        self.assertEqual(child["kind"], "reflected")
        self.assertEqual(child["depth"], 2)
        self.assertFalse(child["hit"])
        self.assertNotIn("lights", child)
        np.testing.assert_allclose(child["direction"], (0, 0, 1), atol=1e-12)
        np.testing.assert_allclose(child["radiance"], (0.1, 0.2, 0.3), rtol=1e-12)
        self.assertEqual(prism.ray_tree(prism.parse(MIRROR_WALL), 2, 2, depth=1)["children"], [])

    def test_a_shadowed_light_names_its_blocker(self):
        # A square at z = 2 round the axis, between the light at (0, 0, 5) and
        # the wall's centre; the eye moved to (3, 0, 5) passes it at x = 1.2
        # and sees the centre in the square's shadow: ambient alone, C 0.1.
        scene = prism.parse(WALL + "polygon 4  -1 -1 2  1 -1 2  1 1 2  -1 1 2\n", name="wall.sc")
        scene.set_camera(eye=(3, 0, 5))
        tree = prism.ray_tree(scene, 2, 2)
        np.testing.assert_allclose(tree["point"], (0, 0, 0), atol=1e-12)
        self.assertEqual(tree["primitive"], "polygon #0 (wall.sc:5)")
        light = tree["lights"][0]
        self.assertTrue(light["shadowed"])
        self.assertEqual(light["blocker"], "polygon #1 (wall.sc:6)")
        np.testing.assert_allclose(tree["radiance"], C * 0.1, rtol=1e-12)

    def test_the_printout_is_prism_render_pixels(self):
        text = prism.ray_tree_text(prism.parse(WALL), 2, 2)
        self.assertIn("pixel (2, 2) of 5 x 5", text)
        self.assertIn("radiance                = (0.18, 0.09, 0.045)", text)

    def test_a_pixel_outside_the_picture_is_a_value_error(self):
        with self.assertRaisesRegex(ValueError, "outside"):
            prism.ray_tree(prism.parse(WALL), 5, 0)


class SceneTest(unittest.TestCase):
    def test_a_scene_error_says_where_and_what(self):
        with self.assertRaises(prism.SceneError) as caught:
            prism.parse("sphere 0 0 0\n", name="broken.sc")
        error = caught.exception
        self.assertIsInstance(error, ValueError)
        self.assertTrue(str(error).startswith("broken.sc:1:"), str(error))
        self.assertIn("error:", str(error))
        self.assertEqual(error.diagnostics[0][:2], ("broken.sc", 1))

    def test_every_error_of_a_file_is_a_line(self):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "two.sc")
            with open(path, "w") as f:
                f.write("resolution 5 5\nsphere 0 0 0 -1\nfrobnicate\n")
            with self.assertRaises(prism.SceneError) as caught:
                prism.load(path)
        lines = str(caught.exception).splitlines()
        self.assertEqual(len(lines), 2, lines)
        self.assertTrue(lines[0].startswith(path + ":2:"), lines)
        self.assertTrue(lines[1].startswith(path + ":3:1: error:"), lines)
        with self.assertRaises(prism.SceneError):
            prism.load("no/such/scene.sc")

    def test_a_shipped_scene_loads_from_a_path(self):
        root = os.environ.get("PRISM_SOURCE_DIR",
                              os.path.join(os.path.dirname(__file__), "..", ".."))
        scene = prism.load(os.path.join(root, "scenes", "table.sc"))
        self.assertGreater(scene.width, 0)
        self.assertGreater(len(scene.lights), 0)
        img = prism.render(scene, width=16, height=12, depth=2)
        self.assertEqual(img.shape, (12, 16, 3))
        self.assertGreater(img.avgmax, 0)

    def test_camera_and_lights_read_as_written(self):
        scene = prism.parse(WALL)
        self.assertEqual(scene.camera, {"eye": (0.0, 0.0, 5.0), "lookat": (0.0, 0.0, 0.0),
                                        "up": (0.0, 1.0, 0.0), "fov": 45.0})
        self.assertEqual(scene.lights, [((0.0, 0.0, 5.0), (4.0, 4.0, 4.0))])
        self.assertEqual(scene.warnings, [])
        self.assertEqual(repr(scene), "<prism.Scene '<string>' 5 x 5 primitives=1 lights=1>")

    def test_edited_lights_and_camera_change_the_next_render(self):
        scene = prism.parse(WALL)

        def centre_now():
            return centre(prism.render(scene, antialias=False))

        # Twice the light: C 0.5 (0.2 + 0.32) = C 0.26.
        scene.set_light(0, intensity=(8, 8, 8))
        self.assertEqual(scene.lights[0], ((0.0, 0.0, 5.0), (8.0, 8.0, 8.0)))
        np.testing.assert_allclose(centre_now(), C * 0.26, rtol=1e-6)
        # A second light of 4 at distance 10 on the axis: + C 0.5 * 4/100 = C 0.02.
        scene.add_light((0, 0, 10), (4, 4, 4))
        self.assertEqual(len(scene.lights), 2)
        np.testing.assert_allclose(centre_now(), C * 0.28, rtol=1e-6)
        # The first light moved to distance 10 too: C 0.5 (0.2 + 0.08 + 0.04) = C 0.16.
        scene.set_light(0, position=np.array([0.0, 0.0, 10.0]))
        np.testing.assert_allclose(centre_now(), C * 0.16, rtol=1e-6)
        scene.remove_light(0)
        scene.remove_light(0)
        # Ambient alone: C 0.5 0.2 = C 0.1.
        np.testing.assert_allclose(centre_now(), C * 0.1, rtol=1e-6)
        # The eye moved back to z = 10 still sees the wall's centre head on.
        scene.set_camera(eye=(0, 0, 10))
        self.assertEqual(scene.camera["eye"], (0.0, 0.0, 10.0))
        self.assertEqual(scene.camera["fov"], 45.0)  # what was not given stays
        scene.add_light([0, 0, 10], [4, 4, 4])
        np.testing.assert_allclose(centre_now(), C * 0.12, rtol=1e-6)

    def test_edits_out_of_range_are_refused_and_nothing_changes(self):
        scene = prism.parse(WALL)
        with self.assertRaisesRegex(ValueError, "eye and lookat are the same point"):
            scene.set_camera(lookat=(0, 0, 5))
        with self.assertRaises(ValueError):
            scene.set_camera(fov=180)
        self.assertEqual(scene.camera["lookat"], (0.0, 0.0, 0.0))
        with self.assertRaises(IndexError):
            scene.set_light(1, intensity=(1, 1, 1))
        with self.assertRaises(IndexError):
            scene.remove_light(3)
        with self.assertRaisesRegex(ValueError, "intensity"):
            scene.add_light((0, 0, 0), (-1, 0, 0))
        with self.assertRaises(ValueError):
            scene.add_light((0, 0, 0), (float("nan"), 0, 0))
        with self.assertRaises(TypeError):
            scene.add_light((0, 0), (1, 1, 1))
        self.assertEqual(len(scene.lights), 1)


class ProgressTest(unittest.TestCase):
    # 256 x 256 is 64 tiles of 32 x 32 a pass; one thread renders them in turn.
    OPTIONS = {"width": 256, "height": 256, "threads": 1}

    def setUp(self):
        # Python turns SIGINT into KeyboardInterrupt only if SIGINT was not
        # ignored when it started, and a shell's background job (`... &`)
        # starts with it ignored: the Ctrl-C tests then failed. Set the
        # handler for the length of each test.
        self._sigint = signal.signal(signal.SIGINT, signal.default_int_handler)
        self.addCleanup(signal.signal, signal.SIGINT, self._sigint)

    def test_progress_rises_to_the_whole_on_the_calling_thread(self):
        calls = []
        prism.render(prism.parse(WALL), progress=lambda p, f: calls.append(
            (p, f, threading.get_ident())), **self.OPTIONS)
        self.assertGreaterEqual(len(calls), 64)
        fractions = [f for _, f, _ in calls]
        self.assertEqual(fractions, sorted(fractions))
        self.assertEqual(fractions[-1], 1.0)
        self.assertEqual({p for p, _, _ in calls}, {1, 2})
        self.assertEqual({t for _, _, t in calls}, {threading.get_ident()})

    def test_ctrl_c_stops_the_render(self):
        fractions = []

        def progress(pass_, fraction):
            fractions.append(fraction)
            if len(fractions) == 1:
                os.kill(os.getpid(), signal.SIGINT)

        with self.assertRaises(KeyboardInterrupt):
            prism.render(prism.parse(WALL), progress=progress, **self.OPTIONS)
        # Stopped within pass 1: the render ended early.
        self.assertGreaterEqual(len(fractions), 1)
        self.assertLess(max(fractions), 0.5)

    def test_ctrl_c_while_rendering_in_cpp_stops_the_render(self):
        # The callback is a C function (SimpleQueue.put(pass_, fraction)),
        # which runs no Python code that could notice the signal: only the
        # render's own wait loop can. Another thread sends SIGINT once the
        # first tile is done.
        tiles = queue.SimpleQueue()

        def interrupt():
            tiles.get()
            os.kill(os.getpid(), signal.SIGINT)

        thread = threading.Thread(target=interrupt)
        thread.start()
        try:
            with self.assertRaises(KeyboardInterrupt):
                prism.render(prism.parse(WALL), progress=tiles.put, width=512, height=512,
                             threads=1)
        finally:
            tiles.put(None)  # should the render have ended before the first tile
            thread.join()
        delivered = 0
        while not tiles.empty():
            tiles.get()
            delivered += 1
        # Stopped within pass 1 (256 tiles of 512): the render ended early.
        self.assertLess(delivered, 256)

    def test_an_exception_in_the_callback_stops_the_render(self):
        fractions = []

        def progress(pass_, fraction):
            fractions.append(fraction)
            raise ZeroDivisionError("enough")

        with self.assertRaisesRegex(ZeroDivisionError, "enough"):
            prism.render(prism.parse(WALL), progress=progress, **self.OPTIONS)
        self.assertEqual(len(fractions), 1)

    def test_the_scene_cannot_change_under_its_render(self):
        scene = prism.parse(WALL)

        def progress(pass_, fraction):
            scene.add_light((0, 0, 1), (1, 1, 1))

        with self.assertRaisesRegex(RuntimeError, "being rendered"):
            prism.render(scene, progress=progress, **self.OPTIONS)
        self.assertEqual(len(scene.lights), 1)
        scene.add_light((0, 0, 1), (1, 1, 1))  # allowed again once it ended
        self.assertEqual(len(scene.lights), 2)

    def test_other_threads_run_while_a_render_runs(self):
        # With a switch interval far longer than the render, a thread gets the
        # GIL only when the thread holding it lets it go. The other thread
        # waits for the render's first tile, then marks that it ran; some
        # later tile's callback must see the mark: it ran while C++ rendered.
        ran = threading.Event()
        go = threading.Event()
        seen = []

        def other():
            go.wait()
            ran.set()

        def progress(pass_, fraction):
            seen.append(ran.is_set())
            go.set()

        thread = threading.Thread(target=other)
        interval = sys.getswitchinterval()
        sys.setswitchinterval(1000.0)
        try:
            thread.start()
            prism.render(prism.parse(WALL), progress=progress, **self.OPTIONS)
        finally:
            sys.setswitchinterval(interval)
            go.set()
            thread.join()
        self.assertFalse(seen[0])
        self.assertTrue(any(seen[1:]), "no other thread ran during the render")


if __name__ == "__main__":
    unittest.main()

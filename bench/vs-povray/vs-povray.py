#!/usr/bin/env python3
"""Prism against POV-Ray 3.7 on the same scenes (docs/vs-povray.md).

Each scene is converted with `prism convert SCENE OUT.pov` and rendered by
both programs at the same size, ray depth and thread count. What is measured
is whole-process CPU time (user + system, every thread, parsing included),
from the kernel's accounting of each finished child (getrusage
RUSAGE_CHILDREN), never from the renderers' own reports. The two renderers
alternate, scene by scene and repeat by repeat, so that a change in the
machine's load hurts both alike; with --repeat N the smallest of the N
figures is kept.

Usage:
  bench/vs-povray/vs-povray.py [time] [SCENE_OR_DIR ...] [options]
      The CPU table: scene, primitives, POV-Ray CPU, Prism CPU and their ratio,
      with adaptive antialiasing (POV-Ray +A0.1 +AM1 +R4, Prism --thresh 0.1)
      and without (POV-Ray -A, Prism --no-aa), and each one's eye rays per
      pixel (their antialiasing criteria differ, so this says whether the
      antialiased runs did the same work). Scenes are the shipped ones
      (scenes/table.sc, glass.sc, chex.sc, tree.sc) followed by every path
      given: .sc, .nff or .obj files, or directories, whose such files are
      taken in name order (e.g. the output of a generator under tools/).
      Without --no-shipped the shipped scenes come first.
  bench/vs-povray/vs-povray.py compare [SCENE ...] [--size N]
      Renders each scene (default scenes/table.sc and scenes/glass.sc) small,
      without antialiasing, in both; prints the ray counts side by side
      (POV-Ray's from the statistics it prints at the end of a render, Prism's
      from --stats-json) and how far the pictures differ. Both renderers write
      linear radiance (.hdr) and the converted scene gives POV-Ray Prism's
      radiance scale, so both pictures are exposed alike, with Prism's rule
      (value * 128 / avgmax, avgmax from Prism's pass 1, clamped to 255), and
      compared in 8-bit levels: the mean absolute difference over all pixels
      and channels, and the share of pixels off by more than 8 levels.

Options: --prism PATH (default build/prism), --povray PATH (default povray),
--size N (square image; 512 for time, 128 for compare), --depth D (5),
--threads N (2), --repeat N (1), --no-shipped, --keep DIR (keep the converted
scenes and pictures there instead of a temporary folder), --hdr (the time
table's pictures as Radiance .hdr rather than 8-bit PNG: Prism then loads its
OpenImageIO module, about 0.25 s of CPU a run; `compare` always writes .hdr).

Needs python3, POV-Ray 3.7 (Debian: povray) and, for `compare`, oiiotool
(Debian: openimageio-tools). Never run by ctest: POV-Ray is a benchmark peer,
not a dependency.
"""

import argparse
import json
import os
import re
import resource
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SHIPPED = ["scenes/table.sc", "scenes/glass.sc", "scenes/chex.sc", "scenes/tree.sc"]
SCENE_SUFFIXES = {".sc", ".nff", ".obj"}


def child_cpu():
    """User + system seconds of every child waited for so far."""
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def run_timed(cmd, cwd, env=None):
    """Runs cmd; returns (CPU seconds of the process and its threads, stderr)."""
    before = child_cpu()
    done = subprocess.run(cmd, cwd=cwd, env=env, stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, text=True)
    cpu = child_cpu() - before
    if done.returncode != 0:
        sys.exit(f"failed ({done.returncode}): {' '.join(map(str, cmd))}\n{done.stderr[-3000:]}")
    return cpu, done.stderr


def scene_list(paths, shipped):
    scenes = [ROOT / s for s in SHIPPED] if shipped else []
    for p in map(Path, paths):
        if p.is_dir():
            scenes += sorted(f for f in p.iterdir() if f.suffix.lower() in SCENE_SUFFIXES)
        else:
            scenes.append(p)
    return scenes


class Bench:
    def __init__(self, args, work):
        self.args = args
        self.work = work
        # POV-Ray warns on every start when the user has no povray.conf; an
        # empty one in a private HOME keeps its default I/O rules (read and
        # write in the current folder, where it runs) and its output quiet.
        home = work / "home"
        (home / ".povray" / "3.7").mkdir(parents=True, exist_ok=True)
        (home / ".povray" / "3.7" / "povray.conf").touch()
        self.pov_env = dict(os.environ, HOME=str(home))

    def convert(self, scene):
        """Writes NAME.pov beside the pictures; returns (pov path, primitives)."""
        pov = self.work / (scene.stem + ".pov")
        done = subprocess.run([self.args.prism, "convert", scene, pov], stderr=subprocess.PIPE,
                              text=True)
        if done.returncode != 0:
            sys.exit(f"prism convert {scene} failed:\n{done.stderr}")
        m = re.search(r": (\d+) primitives", done.stderr)
        return pov, int(m.group(1)) if m else -1

    def povray(self, pov, aa, size, picture):
        # The picture's format from its name: Radiance .hdr (+FH) or 8-bit PNG (+FN).
        form = "+FH" if picture.suffix == ".hdr" else "+FN"
        cmd = [self.args.povray, f"+I{pov.name}", f"+O{picture.name}", form, f"+W{size}",
               f"+H{size}", "-D", "-P", "+MV3.7", f"+WT{self.args.threads}",
               f"Declare=Prism_Depth={self.args.depth}"]
        cmd += ["+A0.1", "+AM1", "+R4"] if aa else ["-A"]
        return run_timed(cmd, self.work, self.pov_env)

    def prism(self, scene, aa, size, picture, stats=None):
        cmd = [self.args.prism, "render", scene, "-o", picture, "--size", str(size), str(size),
               "--depth", str(self.args.depth), "--threads", str(self.args.threads), "-q"]
        cmd += ["--thresh", "0.1"] if aa else ["--no-aa"]
        if stats:
            cmd += ["--stats-json", stats]
        return run_timed(cmd, self.work)


def time_table(args, bench):
    scenes = scene_list(args.scenes, not args.no_shipped)
    size = args.size or 512
    print(f"# {size} x {size}, depth {args.depth}, {args.threads} threads, "
          f"whole-process CPU seconds (best of {args.repeat}), pictures written as "
          f"{'.hdr' if args.hdr else '8-bit .png'}")
    print("| scene | primitives | AA | POV-Ray CPU s | Prism CPU s | POV / Prism "
          "| eye rays/pixel POV, Prism |")
    print("|---|---:|---|---:|---:|---:|---|")
    stats = bench.work / "prism.json"
    # The pictures are not looked at here, so both write what a user most
    # often would, an 8-bit PNG, unless --hdr: Prism writes .hdr through the
    # OpenImageIO module it loads only for such formats, which adds about
    # 0.25 s of CPU to every run (docs/vs-povray.md).
    form = ".hdr" if args.hdr else ".png"
    for scene in scenes:
        pov, primitives = bench.convert(scene)
        for aa in (True, False):
            best_pov = best_prism = float("inf")
            for _ in range(args.repeat):
                cpu, pov_err = bench.povray(pov, aa, size, bench.work / ("pov" + form))
                best_pov = min(best_pov, cpu)
                cpu, _ = bench.prism(scene, aa, size, bench.work / ("prism" + form), stats)
                best_prism = min(best_prism, cpu)
            # How much each antialiased: their criteria differ (docs/vs-povray.md).
            pov_eye = pov_counts(pov_err)["eye (pixels + samples)"] / (size * size)
            prism_eye = json.load(open(stats))["rays"]["eye"] / (size * size)
            print(f"| {scene.name} | {primitives} | {'on' if aa else 'off'} | {best_pov:.2f} | "
                  f"{best_prism:.2f} | {best_pov / max(best_prism, 1e-9):.2f}x "
                  f"| {pov_eye:.2f}, {prism_eye:.2f} |", flush=True)


# POV-Ray's end-of-render statistics: "Rays: N", "Shadow Ray Tests: N",
# "Reflected Rays: N", "Refracted Rays: N", "Transmitted Rays: N" (the last
# three only when not 0), "Pixels: N   Samples: N".
def pov_counts(stderr):
    def number(label):
        m = re.search(label + r":\s+(\d+)", stderr)
        return int(m.group(1)) if m else 0

    return {"eye (pixels + samples)": number("Pixels") + number("Samples"),
            "all rays POV counts as such": number(r"\bRays"),
            "shadow": number("Shadow Ray Tests"),
            "reflected": number("Reflected Rays"),
            "transmitted (refracted + straight)":
                number("Refracted Rays") + number("Transmitted Rays")}


def picture_difference(pov_hdr, prism_hdr, avgmax, work):
    """Mean |difference| in 8-bit levels under Prism's exposure, and the share
    of pixels off by more than 8 levels in some channel."""
    scale = 128.0 / avgmax if avgmax > 0 else 0.0
    levels = []
    for name, hdr in (("pov", pov_hdr), ("prism", prism_hdr)):
        out = work / f"{name}.levels.txt"
        with open(out, "w") as f:
            subprocess.run(["oiiotool", "--dumpdata", hdr], stdout=f, check=True)
        values = []
        for line in open(out):
            if "Pixel (" in line:
                values.append([min(255.0, round(float(v) * scale))
                               for v in line.split(":")[1].split()[:3]])
        levels.append(values)
    pov, prism = levels
    if len(pov) != len(prism) or not pov:
        return float("nan"), float("nan")
    total = sum(abs(a - b) for p, q in zip(pov, prism) for a, b in zip(p, q))
    off = sum(1 for p, q in zip(pov, prism) if max(abs(a - b) for a, b in zip(p, q)) > 8)
    return total / (3 * len(pov)), off / len(pov)


def compare(args, bench):
    scenes = [Path(s) for s in args.scenes] or [ROOT / "scenes/table.sc", ROOT / "scenes/glass.sc"]
    size = args.size or 128
    for scene in scenes:
        pov, primitives = bench.convert(scene)
        pov_hdr, prism_hdr = bench.work / "pov.hdr", bench.work / "prism.hdr"
        stats = bench.work / "prism.json"
        _, pov_err = bench.povray(pov, False, size, pov_hdr)
        bench.prism(scene, False, size, prism_hdr, stats)
        s = json.load(open(stats))
        ours = {"eye (pixels + samples)": s["rays"]["eye"],
                "all rays POV counts as such": s["rays"]["eye"] + s["rays"]["reflected"]
                + s["rays"]["transmitted"],
                "shadow": s["rays"]["shadow"],
                "reflected": s["rays"]["reflected"],
                "transmitted (refracted + straight)": s["rays"]["transmitted"]}
        theirs = pov_counts(pov_err)
        print(f"## {scene.name}: {primitives} primitives, {size} x {size}, depth {args.depth}, "
              f"no antialiasing")
        print("| rays | POV-Ray | Prism | POV / Prism |")
        print("|---|---:|---:|---:|")
        for key in ours:
            ratio = theirs[key] / ours[key] if ours[key] else float("nan")
            print(f"| {key} | {theirs[key]} | {ours[key]} | {ratio:.3f} |")
        mean, off = picture_difference(pov_hdr, prism_hdr, s["avgmax"], bench.work)
        print(f"\npictures under Prism's exposure (avgmax {s['avgmax']:.4g}): mean |difference| "
              f"{mean:.2f} levels of 255, {100 * off:.1f}% of pixels off by more than 8\n",
              flush=True)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("mode_or_scene", nargs="?", default="time")
    p.add_argument("scenes", nargs="*")
    p.add_argument("--prism", default=str(ROOT / "build/prism"))
    p.add_argument("--povray", default="povray")
    p.add_argument("--size", type=int, default=0)
    p.add_argument("--depth", type=int, default=5)
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--repeat", type=int, default=1)
    p.add_argument("--no-shipped", action="store_true")
    p.add_argument("--keep", default="")
    p.add_argument("--hdr", action="store_true")
    args = p.parse_args()
    mode = args.mode_or_scene
    if mode not in ("time", "compare"):
        args.scenes.insert(0, mode)
        mode = "time"
    if shutil.which(args.povray) is None:
        sys.exit(f"{args.povray}: not found (Debian: apt-get install povray)")
    args.scenes = [str(Path(s).resolve()) for s in args.scenes]
    if args.keep:
        work = Path(args.keep).resolve()
        work.mkdir(parents=True, exist_ok=True)
        run(mode, args, work)
    else:
        with tempfile.TemporaryDirectory(prefix="vs-povray-") as tmp:
            run(mode, args, Path(tmp))


def run(mode, args, work):
    bench = Bench(args, work)
    (time_table if mode == "time" else compare)(args, bench)


if __name__ == "__main__":
    main()

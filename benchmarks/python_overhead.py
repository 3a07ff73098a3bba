#!/usr/bin/python3
"""Python overhead of tessera.PatchModel.synthesize against the C++ call (issue 20 goal: <= 5 %).

Both sides synthesize the same 1024 x 1024 window from the same exemplar, options and seed, in the
same run: the C++ figure is the median `synthesis_ms` that `tessera synth --stats --repeat N`
reports (the synthesize() call alone, its thread pool made once), the Python figure the median wall
time of N `model.synthesize(...)` calls (argument parsing, GIL release, a thread pool per call, the
output array), and of N calls rendering into one reused array (`out=`, the CLI's situation). The two
sides alternate for --rounds rounds; it prints the median of the per-round ratios (`overhead`) and the
ratio of the fastest rounds (`overhead_best`, the least disturbed by other load). It then times each
call against the C++ call's own time measured inside it (`stats=`, `synthesis_ms`): `in_process_overhead`
(new arrays) and `in_process_overhead_out` (out=), the median over all calls of wall / C++ - 1. These
compare the same call in the same process and are the figures the issue's 5 % goal is checked against.

    PYTHONPATH=build/python /usr/bin/python3 benchmarks/python_overhead.py --cli build/bin/tessera
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

import tessera


def cli_ms(cmd):
    """Median synthesis_ms of one `tessera synth --stats --repeat N` run."""
    return json.loads(subprocess.run(cmd, check=True, capture_output=True, text=True).stdout.strip())["synthesis_ms"]


def in_process(model, size, seed, threads, repeat, out):
    """Per call: wall time of model.synthesize against the C++ call's own time inside it (stats=),
    same process, same call: the median of wall / synthesis_ms - 1 over `repeat` calls."""
    ratios, walls = [], []
    for _ in range(repeat):
        st = {}
        t = time.perf_counter()
        model.synthesize(size, size, seed=seed, threads=threads, out=out, stats=st)
        wall = (time.perf_counter() - t) * 1e3
        walls.append(wall)
        ratios.append(wall / st["synthesis_ms"] - 1)
    return statistics.median(ratios), statistics.median(walls)


def python_ms(call, repeat):
    """Median wall time (ms) of `repeat` calls."""
    times = []
    for _ in range(repeat):
        t = time.perf_counter()
        call()
        times.append((time.perf_counter() - t) * 1e3)
    return statistics.median(times)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cli", default=os.environ.get("TESSERA_CLI", "build/bin/tessera"))
    ap.add_argument("--size", type=int, default=1024)
    ap.add_argument("--repeat", type=int, default=21, help="calls per round (each side reports its median)")
    ap.add_argument("--rounds", type=int, default=7, help="alternating C++ / Python rounds")
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--seed", type=int, default=5)
    a = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        ex_path = os.path.join(tmp, "ex.png")
        tessera.write_png(ex_path, tessera.exemplar("rock", 128, 128, seed=1))
        out = os.path.join(tmp, "out.png")
        cmd = [a.cli, "synth", "--exemplar", ex_path, "--size", f"{a.size}x{a.size}", "--out", out, "--seed",
               str(a.seed), "--threads", str(a.threads), "--repeat", str(a.repeat), "--stats"]
        model = tessera.PatchModel(tessera.read_png(ex_path))
        img = model.synthesize(a.size, a.size, seed=a.seed, threads=a.threads)  # warm-up
        buf = np.empty_like(img)
        cpp, new, reused = [], [], []
        for _ in range(a.rounds):  # alternate, so that a burst of load hits both sides alike
            cpp.append(cli_ms(cmd))
            new.append(python_ms(lambda: model.synthesize(a.size, a.size, seed=a.seed, threads=a.threads), a.repeat))
            # into one reused array (out=), as the CLI reuses its output buffer across --repeat
            reused.append(python_ms(
                lambda: model.synthesize(a.size, a.size, seed=a.seed, threads=a.threads, out=buf), a.repeat))
        same = np.array_equal(img, tessera.read_png(out)) and np.array_equal(buf, img)
        # in-process: each call against the C++ time measured inside it (no second process, no other load
        # between the two figures)
        inproc_new, inproc_new_ms = in_process(model, a.size, a.seed, a.threads, a.repeat * a.rounds, None)
        inproc_out, inproc_out_ms = in_process(model, a.size, a.seed, a.threads, a.repeat * a.rounds, buf)
    # per-round ratios (same load), then their median; and the fastest round of each side
    ratio = statistics.median(n / c for n, c in zip(new, cpp))
    ratio_out = statistics.median(r / c for r, c in zip(reused, cpp))
    print(json.dumps({"size": a.size, "threads": a.threads, "repeat": a.repeat, "rounds": a.rounds,
                      "cpp_ms": round(statistics.median(cpp), 3), "python_ms": round(statistics.median(new), 3),
                      "python_out_ms": round(statistics.median(reused), 3),
                      "overhead": round(ratio - 1, 4), "overhead_out": round(ratio_out - 1, 4),
                      "overhead_best": round(min(new) / min(cpp) - 1, 4),
                      "overhead_out_best": round(min(reused) / min(cpp) - 1, 4),
                      "in_process_new_ms": round(inproc_new_ms, 3), "in_process_overhead": round(inproc_new, 4),
                      "in_process_out_ms": round(inproc_out_ms, 3), "in_process_overhead_out": round(inproc_out, 4),
                      "bit_identical": same}))
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/python3
"""Python overhead of tessera.PatchModel.synthesize against the C++ call (issue 20 goal: <= 5 %).

Both sides synthesize the same 1024 x 1024 window from the same exemplar, options and seed, in the
same run: the C++ figure is the median `synthesis_ms` that `tessera synth --stats --repeat N`
reports (the synthesize() call alone, its thread pool made once), the Python figure the median wall
time of N `model.synthesize(...)` calls (argument parsing, GIL release, a thread pool per call, the
output array), and of N calls rendering into one reused array (`out=`, the CLI's situation). Prints both and their ratio; on a loaded machine compare the ratio, not the times.

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


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cli", default=os.environ.get("TESSERA_CLI", "build/bin/tessera"))
    ap.add_argument("--size", type=int, default=1024)
    ap.add_argument("--repeat", type=int, default=15)
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--seed", type=int, default=5)
    a = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        ex_path = os.path.join(tmp, "ex.png")
        tessera.write_png(ex_path, tessera.exemplar("rock", 128, 128, seed=1))
        out = os.path.join(tmp, "out.png")
        cmd = [a.cli, "synth", "--exemplar", ex_path, "--size", f"{a.size}x{a.size}", "--out", out, "--seed",
               str(a.seed), "--threads", str(a.threads), "--repeat", str(a.repeat), "--stats"]
        stats = json.loads(subprocess.run(cmd, check=True, capture_output=True, text=True).stdout.strip())
        cpp_ms = stats["synthesis_ms"]
        model = tessera.PatchModel(tessera.read_png(ex_path))
        model.synthesize(64, 64, seed=a.seed, threads=a.threads)  # warm-up
        times = []
        for _ in range(a.repeat):
            t = time.perf_counter()
            img = model.synthesize(a.size, a.size, seed=a.seed, threads=a.threads)
            times.append((time.perf_counter() - t) * 1e3)
        py_ms = statistics.median(times)
        # into one reused array (out=), as the CLI reuses its output buffer across --repeat
        buf = np.empty_like(img)
        times_out = []
        for _ in range(a.repeat):
            t = time.perf_counter()
            model.synthesize(a.size, a.size, seed=a.seed, threads=a.threads, out=buf)
            times_out.append((time.perf_counter() - t) * 1e3)
        py_out_ms = statistics.median(times_out)
        same = np.array_equal(img, tessera.read_png(out)) and np.array_equal(buf, img)
    print(json.dumps({"size": a.size, "threads": a.threads, "repeat": a.repeat, "cpp_ms": round(cpp_ms, 3),
                      "python_ms": round(py_ms, 3), "overhead": round(py_ms / cpp_ms - 1, 4),
                      "python_out_ms": round(py_out_ms, 3), "overhead_out": round(py_out_ms / cpp_ms - 1, 4),
                      "bit_identical": same}))
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())

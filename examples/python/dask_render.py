#!/usr/bin/env python3
"""Render an N x N patch-synthesis texture into a chunked Zarr array across a Dask cluster.

Patch synthesis is a pure function of (model, seed, window): every C x C chunk of the texture is
rendered on its own, anywhere, as ``model.synthesize(C, C, x, y, seed=S)``, and written straight into
its chunk of a Zarr array, so the whole texture is never held in memory (65536 x 65536 RGBA8 is
16 GiB; each task holds one chunk). The model is built once here, serialized once
(``PatchModel.save()``), scattered once to every worker (``client.scatter(..., broadcast=True)``) and
deserialized at most once per worker (a cache on the worker keyed by the bytes' digest).

    /usr/bin/python3 examples/python/dask_render.py --exemplar E.png --size 4096 --chunk 512 \\
        --seed 7 --out texture.zarr --workers 2

Against a running cluster (every worker must import tessera and see the same --out path):

    dask-scheduler                       # Dask 2022.12 (newer: `dask scheduler`)
    dask-worker tcp://HOST:8786 --nworkers 1 --nthreads 1   # on each machine (newer: `dask worker`)
    /usr/bin/python3 examples/python/dask_render.py ... --scheduler tcp://HOST:8786

The Zarr array at the store's root has shape (N, N, channels), chunks (C, C, channels) and the
exemplar's dtype; it equals ``tessera synth --window X0,Y0,N,N`` with the same exemplar, options and seed.
"""
import argparse
import hashlib
import sys
import time

import numpy as np


def parse_args(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--exemplar", required=True, help="exemplar PNG (8/16-bit, 1-4 channels)")
    p.add_argument("--size", type=int, required=True, help="side N of the N x N texture")
    p.add_argument("--chunk", type=int, default=512, help="side C of the C x C chunks (Zarr chunks and tasks)")
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--out", required=True, help="Zarr store (directory), written at its root")
    p.add_argument("--scheduler", help="address of a running scheduler, e.g. tcp://HOST:8786")
    p.add_argument("--workers", type=int, default=2, help="LocalCluster workers when no --scheduler (default 2)")
    p.add_argument("--threads-per-worker", type=int, default=1,
                   help="threads of each LocalCluster worker and of each chunk's synthesis (default 1)")
    p.add_argument("--no-processes", action="store_true", help="LocalCluster workers as threads of this process")
    p.add_argument("--origin", default="0,0", help="X0,Y0: the texture's window origin (default 0,0)")
    p.add_argument("--patch", type=int, help="patch side (PatchModel patch_width = patch_height)")
    p.add_argument("--overlap", type=int, help="patch overlap")
    p.add_argument("--seams", choices=["feather", "cut"], default="feather", help="seam handling (cut: min-cut)")
    p.add_argument("--chunks-per-task", type=int, default=0,
                   help="chunks one task renders, in order (default: enough for 16 megapixels, "
                        "at least 4 tasks per worker)")
    p.add_argument("--keep-malloc-trim", action="store_true",
                   help="keep Dask's MALLOC_TRIM_THRESHOLD_ for LocalCluster workers (default: removed, see without_malloc_trim)")
    p.add_argument("--compressor", choices=["default", "none"], default="default",
                   help="Zarr compressor: Zarr's default (Blosc) or none")
    return p.parse_args(argv)


# ---- worker side --------------------------------------------------------------------------------

def _model(digest, model_bytes, threads):
    """The worker's PatchModel for these bytes, deserialized once per worker (cached on the worker
    object: this function is shipped by value, so a module-level cache would not persist)."""
    from dask.distributed import get_worker
    try:
        cache = get_worker().__dict__.setdefault("_tessera_models", {})
    except ValueError:  # not on a worker (called directly)
        cache = {}
    m = cache.get(digest)
    if m is None:
        import tessera
        m = cache[digest] = tessera.PatchModel.load(model_bytes, threads=threads)
    return m


def _array(store):
    """The worker's handle on the store's root array, opened once per worker (as _model)."""
    from dask.distributed import get_worker
    import zarr
    try:
        cache = get_worker().__dict__.setdefault("_tessera_arrays", {})
    except ValueError:
        cache = {}
    a = cache.get(store)
    if a is None:
        a = cache[store] = zarr.open(store, mode="r+")
    return a


def render_chunks(model_bytes, digest, store, tiles, x0, y0, seed, threads):
    """Renders each window (x0 + x, y0 + y, w, h) of `tiles` and writes it at [y:y+h, x:x+w] of the
    store's root array, one chunk at a time (a task holds one chunk in memory)."""
    import numcodecs.blosc
    # Blosc compresses on a thread per core by default: the tasks already run side by side, one per
    # worker thread, so compress on the task's own thread instead of competing for the same cores
    numcodecs.blosc.use_threads = False
    model = _model(digest, model_bytes, threads)
    array = _array(store)
    # one output buffer for the task's chunks (synthesize(out=...)): a new array per chunk costs page
    # faults that are a third of the synthesis time under Dask's worker allocator settings
    buffer = np.empty((max(h for *_, h in tiles), max(w for _, _, w, _ in tiles), model.channels), model.dtype)
    pixels = 0
    for x, y, w, h in tiles:
        out = model.synthesize(w, h, x=x0 + x, y=y0 + y, seed=seed, threads=threads,
                               out=buffer[:h, :w] if model.channels > 1 else buffer[:h, :w, 0])
        array[y:y + h, x:x + w, :] = out.reshape(h, w, model.channels)
        pixels += w * h
    return pixels


def prepare_worker(model_bytes, digest, store, threads):
    """Deserializes the model and opens the store on this worker (both cached for its tasks)."""
    _model(digest, model_bytes, threads)
    _array(store)
    return 0


# ---- driver -------------------------------------------------------------------------------------

def build_model(args):
    import tessera
    exemplar = tessera.read_png(args.exemplar)
    options = {"seams": args.seams == "cut"}
    if args.patch is not None:
        options.update(patch_width=args.patch, patch_height=args.patch)
    if args.overlap is not None:
        options["overlap"] = args.overlap
    return tessera.PatchModel(exemplar, **options)


def chunks(n, c):
    for y in range(0, n, c):
        for x in range(0, n, c):
            yield x, y, min(c, n - x), min(c, n - y)


def tasks(n, c, per_task):
    """The chunks in groups of `per_task` consecutive chunks of one chunk row (one task each)."""
    group = []
    for tile in chunks(n, c):
        if group and (len(group) == per_task or tile[1] != group[0][1]):
            yield group
            group = []
        group.append(tile)
    if group:
        yield group


def render(args, client, model):
    """Creates the Zarr array, prepares every worker and renders every chunk on `client`; returns
    (pixels, seconds of the render, seconds of the workers' preparation)."""
    import zarr
    from dask.distributed import as_completed
    n, c = args.size, args.chunk
    if n < 1 or c < 1:
        raise SystemExit(f"--size and --chunk must be >= 1, got {n} and {c}")
    x0, y0 = (int(v) for v in args.origin.split(","))
    compressor = None if args.compressor == "none" else "default"
    kwargs = {} if compressor == "default" else {"compressor": None}
    zarr.open(args.out, mode="w", shape=(n, n, model.channels), chunks=(c, c, model.channels),
              dtype=model.dtype, **kwargs)
    model_bytes = model.save()
    digest = hashlib.sha256(model_bytes).hexdigest()
    # start-up: the model shipped once to each worker, deserialized there and the store opened there
    # (the timed render is then the steady state that a larger render amortizes this against)
    ready = time.perf_counter()
    shipped = client.scatter(model_bytes, broadcast=True)
    workers = list(client.scheduler_info()["workers"])
    client.gather([client.submit(prepare_worker, shipped, digest, args.out, args.threads_per_worker, workers=[w],
                                 allow_other_workers=False, pure=False, key=f"tessera-prepare-{digest[:12]}-{i}")
                   for i, w in enumerate(workers)])
    # a task renders enough chunks to amortize Dask's cost per task: 5-7 ms of scheduler and client
    # CPU, measured with 4-megapixel tasks on 2 workers, which took a third of a core the workers
    # needed; up to 16 megapixels a task, yet at least 4 tasks per worker so that all of them work
    chunk_count = ((n + c - 1) // c) ** 2
    per_task = args.chunks_per_task or max(1, min((16 << 20) // (c * c), chunk_count // (4 * len(workers))))
    start = time.perf_counter()
    startup = start - ready
    pixels = 0
    # a bounded number of tasks in flight: a 65536^2 render in 512^2 chunks is 16384 chunks
    pending = tasks(n, c, per_task)
    window = max(16, 4 * len(client.scheduler_info()["workers"]))

    def submit(group):
        x, y = group[0][:2]
        return client.submit(render_chunks, shipped, digest, args.out, group, x0, y0, args.seed,
                             args.threads_per_worker, key=f"tessera-chunks-{digest[:12]}-{x}-{y}", pure=False)

    ac = as_completed([submit(t) for _, t in zip(range(window), pending)])
    for fut in ac:
        pixels += fut.result()
        nxt = next(pending, None)
        if nxt is not None:
            ac.add(submit(nxt))
    return pixels, time.perf_counter() - start, startup


def without_malloc_trim():
    """Starts LocalCluster workers without the MALLOC_TRIM_THRESHOLD_ that Dask sets for them
    (distributed.nanny.pre-spawn-environ). Setting it turns off glibc's adaptive mmap threshold, so
    every allocation above 128 KiB (the synthesis' per-window tables, Zarr's chunk buffers) is a fresh
    mmap and page-faults: synthesis ran 1.3-1.65x slower in the workers than in a plain process."""
    import dask
    environ = dict(dask.config.get("distributed.nanny.pre-spawn-environ", {}))
    environ.pop("MALLOC_TRIM_THRESHOLD_", None)
    dask.config.set({"distributed.nanny.pre-spawn-environ": environ})


def main(argv=None):
    args = parse_args(argv)
    from dask.distributed import Client, LocalCluster
    t0 = time.perf_counter()
    model = build_model(args)
    t_model = time.perf_counter() - t0
    if args.scheduler:
        client = Client(args.scheduler)
        cluster = None
    else:
        if not args.keep_malloc_trim:
            without_malloc_trim()
        cluster = LocalCluster(n_workers=args.workers, threads_per_worker=args.threads_per_worker,
                               processes=not args.no_processes, dashboard_address=None)
        client = Client(cluster)
    try:
        workers = len(client.scheduler_info()["workers"])
        pixels, seconds, startup = render(args, client, model)
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    mps = pixels / seconds / 1e6
    print(f"rendered {args.size} x {args.size} x {model.channels} {np.dtype(model.dtype).name} in "
          f"{args.chunk}^2 chunks on {workers} worker(s): {seconds:.2f} s, {mps:.2f} megapixels/s "
          f"(model built in {t_model:.2f} s, shipped to and loaded on the workers in {startup:.2f} s) -> {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/python3
"""`probeproxy layout` with its candidate stage and its final proxy builds on a Dask cluster.

The candidate stage (every capture point's sight of the floor and the floor its proxies serve)
is most of a layout's time, and its capture points are independent: this script cuts them into
square tiles of the floor (--tile-size), sends each tile to a Dask worker, and lays the level
out from what comes back, writing what `probeproxy layout LEVEL --out DIR --tile-size M` writes,
byte for byte (layout.json's timings aside). Each worker reads the level from the path it is
given (a path every worker shares: the same machine, NFS, a shared bucket mount) once, walks its
floor and lays its capture points as the layout does, and keeps them for every tile it is sent;
what travels back is each tile's packed candidates (sights and served floor samples as Roaring
bitmaps, no meshes: layout.json's candidate_wire_bytes). Once the probes are chosen, their final
proxies are built on the workers too, a task a probe: out goes its name, capture point,
influence volume and fit radius, back its whole build (every candidate proxy tried, the one
kept). A worker lost in the middle costs only its tiles or probes, which Dask runs again
elsewhere: the layout is the same.

  /usr/bin/python3 scripts/layout_dask.py LEVEL_OR_SCENE --out DIR
      (--scheduler tcp://HOST:8786 | --local-workers N) [--tile-size 16]
      [--module-dir build/plugin/python] [--tolerance-deg D] [--max-probes N] [--spacing M]
      [--max-candidates N] [--reach M] [--capture-height M] [--blend-band M]
      [--worker-threads N]

--scheduler joins a running cluster (`dask-scheduler` and `dask-worker`s, `dask-ssh`, a SLURM
queue through dask-jobqueue); --local-workers starts N worker processes on this machine, on
loopback. Every worker needs Debian's python3-distributed and this module (--module-dir, a
path on the worker). --kill-a-worker-after K (for the tests) ends one worker's process once K
tiles are done, and another once K proxy builds are done.
"""
import argparse
import os
import signal
import sys

LAYOUT_OPTIONS = {  # flag: key of probeproxy_py's layout options, type
    "--tolerance-deg": ("tolerance_deg", float),
    "--max-probes": ("max_probes", int),
    "--spacing": ("spacing", float),
    "--max-candidates": ("max_candidates", int),
    "--reach": ("reach", float),
    "--capture-height": ("capture_height", float),
    "--blend-band": ("blend_band", float),
}


def layout_worker(module_dir, level, options):
    """On a worker: its probeproxy_py.LayoutWorker for this level and options, made once per
    worker process (the level read, its floor walked, its capture points laid)."""
    from distributed import get_worker
    if module_dir not in sys.path:
        sys.path.insert(0, module_dir)
    import probeproxy_py
    workers = get_worker().__dict__.setdefault("probeproxy_layout_workers", {})
    key = (level, tuple(sorted(options.items())))
    if key not in workers:
        workers[key] = probeproxy_py.LayoutWorker(level, dict(options))
    return workers[key]


def judge_tile(module_dir, level, options, captures):
    """On a worker: the packed candidates of one tile's capture points."""
    return layout_worker(module_dir, level, options).judge(captures)


def build_proxy(module_dir, level, options, task):
    """On a worker: the packed final proxy of one laid-out probe."""
    return layout_worker(module_dir, level, options).build_proxy(task)


def end_one_worker(client):
    """Ends one worker's process (the one with the lowest address), as a machine lost would."""
    pids = client.run(os.getpid)
    address = sorted(pids)[0]
    os.kill(pids[address], signal.SIGKILL)
    return address


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("level_or_scene")
    parser.add_argument("--out", required=True)
    where = parser.add_mutually_exclusive_group(required=True)
    where.add_argument("--scheduler", help="address of a running Dask scheduler")
    where.add_argument("--local-workers", type=int, help="start this many worker processes here")
    parser.add_argument("--tile-size", type=float, default=16.0,
                        help="square tiles of the floor, m (default 16)")
    parser.add_argument("--module-dir", default=os.path.join("build", "plugin", "python"),
                        help="where probeproxy_py is, on this machine and on every worker")
    parser.add_argument("--worker-threads", type=int, default=0,
                        help="threads each worker's judge uses (0: all its cores)")
    parser.add_argument("--kill-a-worker-after", type=int, default=0, help=argparse.SUPPRESS)
    for flag, (_, kind) in LAYOUT_OPTIONS.items():
        parser.add_argument(flag, type=kind)
    args = parser.parse_args()

    module_dir = os.path.abspath(args.module_dir)
    sys.path.insert(0, module_dir)
    import probeproxy_py
    from distributed import Client, LocalCluster, as_completed

    level = os.path.abspath(args.level_or_scene)
    options = {"tile_size": args.tile_size}
    for flag, (key, _) in LAYOUT_OPTIONS.items():
        value = getattr(args, flag[2:].replace("-", "_"))
        if value is not None:
            options[key] = value
    worker_options = dict(options, threads=args.worker_threads)

    if args.scheduler:
        cluster, client = None, Client(args.scheduler)
    else:
        cluster = LocalCluster(n_workers=args.local_workers, threads_per_worker=1,
                               processes=True, host="127.0.0.1", dashboard_address=None)
        client = Client(cluster)
    workers = len(client.scheduler_info().get("workers", {}))
    ended = []  # the workers ended, one per stage with --kill-a-worker-after
    proxy_travel = {"builds": 0, "out": 0, "back": 0}  # bytes of the tasks sent, builds back

    def run_everywhere(task, items):
        """Maps task over items on the cluster, in order; with --kill-a-worker-after K, one
        worker's process is ended once K of them are done (and Dask runs its share again)."""
        futures = client.map(task, [module_dir] * len(items), [level] * len(items),
                             [worker_options] * len(items), items, pure=False)
        if args.kill_a_worker_after > 0:
            for done, _ in enumerate(as_completed(futures), start=1):
                if done == args.kill_a_worker_after:
                    ended.append(end_one_worker(client))
                    break
        return client.gather(futures)

    def judge_tiles(tiles):
        return run_everywhere(judge_tile, tiles)

    def build_proxies(tasks):
        builds = run_everywhere(build_proxy, tasks)
        proxy_travel.update(builds=len(tasks), out=sum(map(len, tasks)),
                            back=sum(map(len, builds)))
        return builds

    try:
        result = probeproxy_py.layout_level(level, args.out, options, judge_tiles=judge_tiles,
                                            build_proxies=build_proxies)
    except probeproxy_py.InputError as error:
        print("layout_dask: error: %s" % error, file=sys.stderr)
        return 2
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    figures = result["figures"]
    ended_note = ""
    if ended:
        ended_note = " (one ended after %d tiles%s)" % (
            args.kill_a_worker_after,
            " and one after %d proxy builds" % args.kill_a_worker_after if len(ended) > 1 else "")
    print("%d probes from %d capture points in %d tiles on %d workers%s; %d bytes of candidates "
          "came back; %d proxy builds: %d bytes of tasks out, %d bytes of builds back"
          % (figures["probes"], figures["capture_points"], figures.get("candidate_tiles", 1),
             workers, ended_note, figures.get("candidate_wire_bytes", 0),
             proxy_travel["builds"], proxy_travel["out"], proxy_travel["back"]))
    for path in result["files"]:
        print("wrote %s" % path, file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""A discrete-event model of glint-mpi's schedule (src/glint/cluster/cluster_render.cpp), fed with
measured times, to predict how a render scales past the ranks one machine can show.

The model follows the code: each rank (rank 0 too) asks for two pieces per thread, rank 0 answers
one message at a time (a queue), handing out ready pieces lowest pass first (a tile's next pass
only once its last is back), each message costs the network's latency and its bytes over the
bandwidth, a rank renders its batch on its threads (longest piece first), and at the end the
films are summed along MPI's reduction tree (ceil(log2 ranks) steps of one film each). Frames of
an animation, when ranks share frames, go out the same way, a frame at a time to a rank.

  python3 bench/cluster/model.py --tiles times.json --pingpong latency.json
"""

import argparse
import heapq
import json
import math


def piece_times_4k(measured, width=3840, height=2160, tile=16):
    """A piece time for each tile of the frame: the measured tile at the same place of the image
    (a tile's 256 pixels cost about what 256 pixels cost there, whatever the resolution)."""
    mw = (measured["width"] + tile - 1) // tile
    mh = (measured["height"] + tile - 1) // tile
    tw, th = (width + tile - 1) // tile, (height + tile - 1) // tile
    s = measured["seconds"]
    return [s[min(mh - 1, y * mh // th) * mw + min(mw - 1, x * mw // tw)]
            for y in range(th) for x in range(tw)]


def makespan(times, threads):
    """The time `threads` threads take for these pieces, longest first to the least loaded."""
    loads = [0.0] * threads
    for t in sorted(times, reverse=True):
        i = loads.index(min(loads))
        loads[i] += t
    return max(loads) if times else 0.0


def frame(tiles, passes, ranks, threads, net, film_bytes, service, carry_bytes):
    """Seconds to render one frame of `tiles` (one-thread seconds of a piece) through `passes`."""
    ready = [(0, t) for t in range(len(tiles))]
    heapq.heapify(ready)
    left = len(tiles) * passes
    events = [(0.0 if r == 0 else net["latency"], r) for r in range(ranks)]
    heapq.heapify(events)
    root_free = 0.0
    finished = 0.0
    waiting = []  # ranks that asked when nothing was ready: (their ask's arrival, rank)
    held = {}
    batch = 2 * threads
    while events:
        t, r = heapq.heappop(events)
        results = held.pop(r, [])
        for pass_, tile in results:  # its results: those tiles' next passes are ready
            left -= 1
            if pass_ + 1 < passes:
                heapq.heappush(ready, (pass_ + 1, tile))
        if left == 0:
            finished = max(finished, t)
        if results:  # ranks that found nothing ready ask again
            for w in waiting:
                heapq.heappush(events, (t, w))
            waiting = []
        start = max(t, root_free)
        pieces = [heapq.heappop(ready) for _ in range(min(batch, len(ready)))]
        root_free = start + (0 if r == 0 else service + len(pieces) * carry_bytes * 2 / 1e9)
        if not pieces:
            if left > 0:
                waiting.append(r)
            continue
        hop = 0 if r == 0 else net["latency"] + len(pieces) * carry_bytes / net["bandwidth"]
        done = root_free + hop + makespan([tiles[tile] for _, tile in pieces], threads)
        held[r] = pieces
        heapq.heappush(events, (done + hop, r))
    steps = math.ceil(math.log2(ranks)) if ranks > 1 else 0
    # Each step: one film over the network and added (16-byte integers, about 2 GB/s).
    reduce = steps * (net["latency"] + film_bytes / net["bandwidth"] + film_bytes / 2e9)
    return finished + reduce, reduce


def animation(frame_seconds, frames, ranks, net):
    """Frames handed out a frame at a time to whichever rank asks: the last frames' tail."""
    free = [(0.0, r) for r in range(ranks)]
    heapq.heapify(free)
    end = 0.0
    for _ in range(frames):
        t, r = heapq.heappop(free)
        t += net["latency"] * 2 + frame_seconds
        end = max(end, t)
        heapq.heappush(free, (t, r))
    return end


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--tiles", required=True, help="tile_times output (one pass's pieces)")
    ap.add_argument("--pingpong", required=True, help="pingpong output (this machine's MPI)")
    ap.add_argument("--passes", type=int, default=4, help="passes of the frame (64 spp in 16s)")
    ap.add_argument("--threads", type=int, default=32, help="threads of each rank (a node)")
    ap.add_argument("--frames", type=int, default=1000)
    args = ap.parse_args()
    measured = json.load(open(args.tiles))
    rt = json.load(open(args.pingpong))["round_trip_seconds"]
    tiles = piece_times_4k(measured)
    carry_bytes = 256 * (4 + 16) + 32  # samples and one-pixel sums of a tile, its header
    film_bytes = 3840 * 2160 * 64       # a filter wider than a pixel: 4 x 128-bit sums a pixel
    nets = {
        # This machine's shared memory, measured: half a round trip of 64 bytes; the bandwidth
        # from 4 MiB round trips.
        "this machine (shared memory, measured)": {
            "latency": rt["64"] / 2, "bandwidth": 4194304 / (rt["4194304"] / 2)},
        # Typical figures, not measured here.
        "10 Gb Ethernet (assumed: 25 us, 1.1 GB/s)": {"latency": 25e-6, "bandwidth": 1.1e9},
        "InfiniBand HDR (assumed: 1.5 us, 12 GB/s)": {"latency": 1.5e-6, "bandwidth": 12e9},
    }
    service = 20e-6  # rank 0's own time a message beside the bytes (assumed; decode, encode)
    work = sum(tiles) * args.passes  # one thread's seconds for the frame
    print("4K frame: %d tiles x %d passes, %.1f one-thread seconds of work (measured %s at %dx%d, "
          "%d spp a pass)" % (len(tiles), args.passes, work, measured["scene"].split("/")[-1],
                              measured["width"], measured["height"], measured["spp"]))
    print()
    print("| network | ranks (x %d threads) | frame s | of which the sum s | efficiency | "
          "%d frames s | efficiency |" % (args.threads, args.frames))
    print("|---|---:|---:|---:|---:|---:|---:|")
    for name, net in nets.items():
        for ranks in (1, 16, 64, 1024):
            seconds, reduce = frame(tiles, args.passes, ranks, args.threads, net, film_bytes,
                                    service, carry_bytes)
            one, _ = frame(tiles, args.passes, 1, args.threads, net, film_bytes, service,
                           carry_bytes)
            anim = animation(one, args.frames, ranks, net)
            ideal_frame = work / (ranks * args.threads)
            ideal_anim = args.frames * one / ranks
            print("| %s | %d | %.3f | %.3f | %.0f%% | %.0f | %.0f%% |" % (
                name, ranks, seconds, reduce, 100 * ideal_frame / seconds, anim,
                100 * ideal_anim / anim))


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""The H1 estimate of tests/bench/signal_h1_bench.cpp done with SciPy.

4 channels (1 force + 3 responses) x 65536 samples x 10 hits, rectangular
window, one segment per hit, averaged over the hits: scipy.signal.welch for
G_ff and G_xx, scipy.signal.csd for G_fx. Prints the best of several runs in
CPU time (time.process_time, comparable with Google Benchmark's CPU column on
a shared machine; SciPy's FFT here is single-threaded).

    /usr/bin/python3 tests/bench/signal_h1_scipy.py [--repeat N]   # Debian python3-scipy

Figures are recorded in docs/performance/signal.md.
"""
import argparse
import time
import timeit

import numpy as np
import scipy
from scipy import signal

N, CH, HITS, FS = 65536, 4, 10, 8192.0


def h1(data, coherence):
    f = data[0]
    kw = dict(fs=FS, window="boxcar", nperseg=N, noverlap=0, detrend=False)
    _, gff = signal.welch(f, **kw)
    out = []
    for x in data[1:]:
        _, gfx = signal.csd(f, x, **kw)
        h = gfx / gff
        if coherence:
            _, gxx = signal.welch(x, **kw)
            out.append((h, np.abs(gfx) ** 2 / (gff * gxx)))
        else:
            out.append(h)
    return out


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--repeat", type=int, default=7)
    a = p.parse_args()
    rng = np.random.default_rng(1)
    data = rng.standard_normal((CH, HITS * N))  # the hits back to back, one segment each
    for coh, name in ((False, "H1 only"), (True, "H1 + coherence")):
        t = min(timeit.Timer(lambda: h1(data, coh), timer=time.process_time).repeat(number=1, repeat=a.repeat))
        print(f"scipy {scipy.__version__} {name}: {t * 1e3:.1f} ms")
    # the floor in numpy's FFT: 40 real FFTs of N points
    segs = data.reshape(CH, HITS, N)
    t = min(timeit.Timer(lambda: np.fft.rfft(segs, axis=-1), timer=time.process_time).repeat(number=1, repeat=a.repeat))
    print(f"numpy rfft 40 x {N}: {t * 1e3:.1f} ms")


if __name__ == "__main__":
    main()

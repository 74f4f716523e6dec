#!/usr/bin/env python3
"""Samples for the paint tests, made with numpy apart from the painter: 64 x 64 stochastic.ppm
(periodic low-passed noise in two colours), striped.ppm (stripes along x, a period of 8 pixels
down y, a little noise) and heights.pgm (round bumps on a jittered lattice); and odd.ppm, noise
as stochastic.ppm's at 63 x 47, sides a halving does not divide. All wrap round their borders,
as the painter reads them.

usage: paint_samples.py OUT_DIR [SEED]
"""
import sys

import numpy as np

SIZE = 64
# striped.ppm's two colours (field_stripes.py paints its reference in them).
STRIPE_DARK, STRIPE_LIGHT = np.array([0.85, 0.2, 0.2]), np.array([0.95, 0.95, 0.9])


def write_ppm(path, rgb):
    with open(path, "wb") as f:
        f.write(b"P6\n%d %d\n255\n" % (rgb.shape[1], rgb.shape[0]))
        f.write(np.clip(np.rint(rgb * 255), 0, 255).astype(np.uint8).tobytes())


def write_pgm(path, grey):
    with open(path, "wb") as f:
        f.write(b"P5\n%d %d\n255\n" % (grey.shape[1], grey.shape[0]))
        f.write(np.clip(np.rint(grey * 255), 0, 255).astype(np.uint8).tobytes())


def main():
    out = sys.argv[1]
    rng = np.random.default_rng(int(sys.argv[2]) if len(sys.argv) > 2 else 5)
    n = SIZE

    def two_colours(height, width):
        # Features of a few pixels, the window's scale: noise low-passed round the torus, then two
        # colours by a steep threshold.
        k = np.fft.fftfreq(height)[:, None] ** 2 + np.fft.fftfreq(width)[None, :] ** 2
        noise = np.real(np.fft.ifft2(np.fft.fft2(rng.standard_normal((height, width))) * np.exp(-k / (2 * 0.1 ** 2))))
        t = (1 / (1 + np.exp(-noise / noise.std() * 6)))[..., None]
        return t * np.array([0.9, 0.75, 0.2]) + (1 - t) * np.array([0.15, 0.3, 0.6])

    write_ppm(out + "/stochastic.ppm", two_colours(n, n))
    y = np.arange(n)[:, None] * np.ones((1, n))
    s = (0.5 + 0.5 * np.sin(2 * np.pi * y / 8))[..., None] + 0.03 * rng.standard_normal((n, n, 1))
    write_ppm(out + "/striped.ppm", s * STRIPE_DARK + (1 - s) * STRIPE_LIGHT)
    grey = np.zeros((n, n))
    yy, xx = np.mgrid[0:n, 0:n]
    for cy in range(0, n, 16):
        for cx in range(0, n, 16):
            py, px = cy + 8 + rng.uniform(-3, 3), cx + 8 + rng.uniform(-3, 3)
            dy = np.minimum(abs(yy - py), n - abs(yy - py))
            dx = np.minimum(abs(xx - px), n - abs(xx - px))
            grey = np.maximum(grey, np.clip(1 - (dx ** 2 + dy ** 2) / 36.0, 0, 1))
    write_pgm(out + "/heights.pgm", grey)
    write_ppm(out + "/odd.ppm", two_colours(47, 63))


if __name__ == "__main__":
    main()

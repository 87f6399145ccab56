# How render_check's frames code a level point in colours a baked cubemap keeps: per axis a
# coarse code 1 + (p - lo) / size (one step is 1/64 of the level's size in EEVEE's R11G11B10F)
# and a phase pair 0.5 + 0.5 cos / sin(2 pi p / T) per period T, from FINEST_PERIOD_M up by 8x
# until the coarse code resolves the largest period. Shared by both renderers' frame writers
# and the decoder.

FINEST_PERIOD_M = 1.0
MARGIN_M = 1.0  # lo and size hold the level with this much room: every code stays positive


def bounds(vertices):
    """(lo, size) of the coded box around the level's vertices, per axis."""
    lo = [min(v[a] for v in vertices) - MARGIN_M for a in range(3)]
    size = [max(v[a] for v in vertices) + MARGIN_M - lo[a] for a in range(3)]
    return lo, size


def codes(size):
    """(axis, period) of the coded bakes, coarsest period first per axis."""
    periods = [FINEST_PERIOD_M]
    while max(size) / 64.0 > periods[-1] / 4.0:
        periods.append(periods[-1] * 8.0)
    return [(axis, p) for axis in range(3) for p in reversed(periods)]


def colour(points, lo, size, axis, period):
    """The code colour (coarse, cos, sin) of one (axis, period) bake at level points (n x 3):
    what the frame writers' shaders write, for the decoder's prediction of a blended pixel."""
    import numpy as np
    p = np.asarray(points, dtype=float)[:, axis]
    phase = 2.0 * np.pi * p / period
    return np.stack([1.0 + (p - lo[axis]) / size[axis], 0.5 + 0.5 * np.cos(phase),
                     0.5 + 0.5 * np.sin(phase)], axis=-1)

"""The imperfect joint's overlap in closed form (`model.gapped_overlap`) against the same integral
carried in dual numbers through every segment of the gap profile (the engine's form before issue 45's
speed work, kept here as the oracle): the same values to the bit, the same derivatives to round-off,
in every configuration of a face (touching throughout, in patches, opening at either end, clipped by
the shared part's ends)."""

from __future__ import annotations

import numpy as np
import pytest
from numba import njit

from yadearch.case.config import preset
from yadearch.model.dual import add, const, div, dmax, dmin, mul, scale, shift, sub
from yadearch.model.gapped_overlap import gapped_overlap
from yadearch.solve.statics import static_arch

DERIVATIVE_TOLERANCE = 1e-10  # relative to the largest derivative: round-off of two orders of summation
TRIALS = 2000


@njit(cache=True)
def dual_overlap(p0, slope, start, shared, fraction, gap, projected_length):
    """The oracle: `joint_law._gapped_overlap` segment by segment in dual numbers."""
    area, moment, touching = const(0.0), const(0.0), const(0.0)
    end = add(start, shared)
    for k in range(fraction.shape[0] - 1):
        t0, t1 = mul(const(fraction[k]), projected_length), mul(const(fraction[k + 1]), projected_length)
        a, b = dmax(t0, start), dmin(t1, end)
        if b[0] <= a[0]:
            continue
        rate = div(const(gap[k + 1] - gap[k]), sub(t1, t0))
        ua = sub(sub(p0, mul(slope, sub(a, start))), shift(mul(rate, sub(a, t0)), gap[k]))
        ub = sub(sub(p0, mul(slope, sub(b, start))), shift(mul(rate, sub(b, t0)), gap[k]))
        if ua[0] <= 0.0 and ub[0] <= 0.0:
            continue
        if ua[0] < 0.0:
            a, ua = add(a, div(mul(sub(b, a), ua), sub(ua, ub))), const(0.0)
        elif ub[0] < 0.0:
            b, ub = add(a, div(mul(sub(b, a), ua), sub(ua, ub))), const(0.0)
        width = sub(b, a)
        area = add(area, scale(mul(width, add(ua, ub)), 0.5))
        weighted = add(mul(ua, add(scale(a, 2.0), b)), mul(ub, add(a, scale(b, 2.0))))
        moment = add(moment, scale(mul(width, weighted), 1.0 / 6.0))
        touching = add(touching, width)
    centroid = div(moment, area) if area[0] > 0.0 else const(0.0)
    return area, centroid, touching


@pytest.fixture(scope="module")
def profiles():
    """Set 2's joints with the imperfection study's face bumps: (fractions, gaps, joint length)."""
    arch = static_arch(preset("set2").with_overrides({"imperfections.face_bump_sd_mm": 0.18, "imperfections.seed": 3}))
    fraction, gap, imperfect = arch.table.kernel_gaps()
    assert imperfect.all()
    return fraction, gap, arch.table.length


@pytest.mark.parametrize("pressing", ["lightly", "throughout"])
def test_closed_form_matches_the_dual_numbers_oracle(profiles, pressing):
    fraction, gap, lengths = profiles
    rng = np.random.default_rng(7 if pressing == "lightly" else 8)
    depth = 3e-5 if pressing == "lightly" else 4e-4  # m: the faces touch in patches / nearly everywhere
    compared = 0
    for _ in range(TRIALS):
        j = int(rng.integers(len(gap)))

        def dual(value: float, spread: float) -> tuple:
            return (value, *rng.normal(size=6) * spread)

        start = abs(rng.normal()) * 1e-4
        projected = lengths[j] * (1.0 - 1e-6 * rng.random())
        inputs = (
            dual(depth * rng.normal() + 0.5 * depth, 1e-3),
            dual(2e-3 * rng.normal(), 1e-2),
            dual(start, 1e-3),
            dual(projected - 2.0 * start, 1e-3),
            dual(projected, 1e-3),
        )
        expected = dual_overlap(*inputs[:4], fraction[j], gap[j], inputs[4])
        found = gapped_overlap(*inputs[:4], fraction[j], gap[j], inputs[4])
        if expected[0][0] <= 0.0:
            continue
        compared += 1
        for want, got in zip(expected, found, strict=True):
            assert got[0] == want[0]  # the value: the same arithmetic
            scale_ = np.abs(want[1:]).max()
            np.testing.assert_allclose(got[1:], want[1:], rtol=0.0, atol=DERIVATIVE_TOLERANCE * scale_)
    assert compared > TRIALS // 2


def _finite_difference(inputs: tuple, fraction: np.ndarray, gap: np.ndarray, which: int, step: float) -> np.ndarray:
    """Central differences of (area, centroid, touching) along input `which`'s own direction."""
    values = []
    for sign in (1.0, -1.0):
        moved = tuple((x[0] + sign * step if i == which else x[0], *x[1:]) for i, x in enumerate(inputs))
        found = gapped_overlap(*moved[:4], fraction, gap, moved[4])
        values.append(np.array([found[0][0], found[1][0], found[2][0]]))
    return (values[0] - values[1]) / (2.0 * step)


def test_a_face_that_opens_exactly_at_a_node():
    """The overlap 0 exactly at the profile's middle node, rising to the right: the touching part's left
    end is that node, and it moves with every input as finite differences say."""
    fraction, gap = np.array([0.0, 0.5, 1.0]), np.array([0.2, 0.0, -0.2])
    unit = (0.0,) * 6
    inputs = ((0.0, 1.0, *unit[1:]), (0.0, *unit), (0.1, *unit), (0.8, *unit), (1.0, *unit))
    derivative = gapped_overlap(*inputs[:4], fraction, gap, inputs[4])[2][1]  # d touching / d p0
    assert derivative == pytest.approx(_finite_difference(inputs, fraction, gap, 0, 1e-7)[2], rel=1e-6)
    assert derivative == pytest.approx(2.5)  # 1 / (the overlap's slope along the face, 0.4 / 0.5)

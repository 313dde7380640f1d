"""An imperfect joint's overlap with its exact derivatives in closed form (compiled with numba, no YADE):
the values segment by segment in the arithmetic of the dual-number form it replaces (the value parts
of `tests/model/test_gapped_overlap.py`'s oracle, to the bit), the derivatives by Leibniz's rule over
the touching parts instead of dual numbers carried through every segment of the gap profile
(docs/speed.md: 0.34-0.53 against 0.49-1.67 us a joint).

The overlap at abscissa s is u(s) = p0 - slope (s - start) - g(s) over [start, end = start + shared],
g piecewise linear on the nodes fraction x projected. Differentiating A = int u+ ds, M = int s u+ ds
and the touching length T with respect to p0, slope, start, shared and projected leaves integrals of
1, s, s^2 (and of the gap's rate times s, s^2) over the touching parts, and terms at their ends: the
domain's ends where the faces still press, the crossings u = 0 where they open. The chain rule through
the five duals gives the derivatives over the joint's six degrees of freedom.
"""

from __future__ import annotations

from numba import njit

from yadearch.model.dual import div

INPUTS = 5  # p0, slope, start, shared, projected: what the overlap depends on


@njit(cache=True)
def gapped_overlap(p0, slope, start, shared, fraction, gap, projected):
    """Area (m^2), centroid abscissa and touching length (duals, `model.dual`) of max(0, overlap - gap)
    over the shared abscissae, the gap piecewise linear on the nodes `fraction` x `projected`."""
    p, k_slope, s0, end, length = p0[0], slope[0], start[0], start[0] + shared[0], projected[0]
    area, moment, touching = 0.0, 0.0, 0.0
    w_sum, s1_sum, s2_sum, r1_sum, r2_sum = 0.0, 0.0, 0.0, 0.0, 0.0  # int 1, s, s^2, rate s, rate s^2
    opened, opened_at, opened_rate = 0.0, 0.0, 0.0  # the crossings' terms: sum of +-1/(du/ds), x s, x rate s
    at_start, at_end = 0.0, 0.0  # the overlap at the shared part's ends where the faces press there
    for k in range(fraction.shape[0] - 1):
        t0, t1 = fraction[k] * length, fraction[k + 1] * length
        a = t0 if t0 >= s0 else s0
        b = t1 if t1 <= end else end
        if b <= a:
            continue
        rate = (gap[k + 1] - gap[k]) * (1.0 / (t1 - t0))
        ua = (p - k_slope * (a - s0)) - (rate * (a - t0) + gap[k])
        ub = (p - k_slope * (b - s0)) - (rate * (b - t0) + gap[k])
        if ua <= 0.0 and ub <= 0.0:
            continue
        opens_left, opens_right = ua <= 0.0, ub <= 0.0  # the faces open at that end (u = 0 there, or below)
        if ua < 0.0:
            a, ua = a + ((b - a) * ua) * (1.0 / (ua - ub)), 0.0
        elif ub < 0.0:
            b, ub = a + ((b - a) * ua) * (1.0 / (ua - ub)), 0.0
        if opens_left or opens_right:  # that end moves by -(du/dinput) / (du/ds), u rising toward b or not
            at, weight = (a, -1.0 / (k_slope + rate)) if opens_left else (b, 1.0 / (k_slope + rate))
            opened, opened_at, opened_rate = opened + weight, opened_at + weight * at, opened_rate + weight * rate * at
        if ua > 0.0 and a == s0:
            at_start = ua
        if ub > 0.0 and b == end:
            at_end = ub
        width = b - a
        area += (width * (ua + ub)) * 0.5
        moment += (width * (ua * (a * 2.0 + b) + ub * (a + b * 2.0))) * (1.0 / 6.0)
        touching += width
        s1, s2 = width * (a + b) * 0.5, width * (a * a + a * b + b * b) * (1.0 / 3.0)
        w_sum, s1_sum, s2_sum = w_sum + width, s1_sum + s1, s2_sum + s2
        r1_sum, r2_sum = r1_sum + rate * s1, r2_sum + rate * s2
    start_end = 1.0 if at_start > 0.0 else 0.0  # the touching length's ends at the shared part's ends
    end_end = 1.0 if at_end > 0.0 else 0.0
    d_area = (w_sum, s0 * w_sum - s1_sum, k_slope * w_sum + at_end - at_start, at_end, r1_sum / length)
    d_moment = (
        s1_sum,
        s0 * s1_sum - s2_sum,
        k_slope * s1_sum + end * at_end - s0 * at_start,
        end * at_end,
        r2_sum / length,
    )
    d_touching = (
        opened,
        s0 * opened - opened_at,
        k_slope * opened + end_end - start_end,
        end_end,
        opened_rate / length,
    )
    inputs = (p0, slope, start, shared, projected)
    area_dual = _dual(area, d_area, inputs)
    centroid = (
        div(_dual(moment, d_moment, inputs), area_dual) if area > 0.0 else _dual(0.0, (0.0, 0.0, 0.0, 0.0, 0.0), inputs)
    )
    return area_dual, centroid, _dual(touching, d_touching, inputs)


@njit(cache=True)
def _dual(value, partials, inputs):
    """The dual of `value` whose partial derivatives with respect to the duals `inputs` are `partials`."""
    d0 = d1 = d2 = d3 = d4 = d5 = 0.0
    for i in range(INPUTS):
        c, x = partials[i], inputs[i]
        d0, d1, d2 = d0 + c * x[1], d1 + c * x[2], d2 + c * x[3]
        d3, d4, d5 = d3 + c * x[4], d4 + c * x[5], d5 + c * x[6]
    return (value, d0, d1, d2, d3, d4, d5)

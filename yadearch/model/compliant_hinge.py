"""How close the thrust may come to a joint's edge beside a hinge before a Winkler joint gives way:
the finite-stiffness margin that puts a DEM arch's hinge migrations and collapse ahead of the rigid
blocks' (docs/theory.md, "Compliant hinges").

A joint whose thrust sits a distance a from its edge, pressed by N over a depth b, opens on a
triangular pressure block 3a long by theta = 2N / (9 kn b a^2). Turning it moves the rigid thrust
toward the edge along the four-hinge chain that opens it, by G theta / N, with G the chain's loss of
potential energy per squared turn (about N times one voussoir's length beside a hinge). The joint
holds while a_rigid = a + (G / N) theta(a) has a root: it folds at a_rigid = 3/2 (4 G / (9 kn b))^(1/3),
so the margin falls as kn^(-1/3) and the DEM approaches the rigid limit that slowly.
"""

from __future__ import annotations

FOLD_FACTOR = 1.5  # the fold's rigid margin over the margin the joint itself reaches at the fold
CHAIN_FACTOR = 4.0 / 9.0  # a*^3 = (4/9) G / (kn b): the fold of a + (G/N) 2N/(9 kn b a^2)


def fold_margin(curvature: float, kn: float, depth: float) -> float:
    """The distance (m) from its edge that the rigid thrust of a joint must keep for the Winkler joint
    to hold: `curvature` G (N m per rad^2, the opening chain's loss of potential energy per squared
    turn of the joint), `kn` (N/m^3), `depth` (m). Zero for a joint that does not destabilise (G <= 0)."""
    if kn <= 0 or depth <= 0:
        raise ValueError(f"kn and depth must be positive, got {kn} and {depth}")
    if curvature <= 0:
        return 0.0
    return FOLD_FACTOR * (CHAIN_FACTOR * curvature / (kn * depth)) ** (1.0 / 3.0)


def joint_turn(normal_force: float, margin: float, kn: float, depth: float) -> float:
    """The turn (rad) a Winkler joint pressed by `normal_force` (N) opens to when its thrust sits
    `margin` (m) from its edge: the pressure block is 3 x margin long (partial contact only)."""
    return 2.0 * normal_force / (9.0 * kn * depth * margin**2)

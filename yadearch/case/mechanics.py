"""Contact mechanics of the dry joints, in pure Python: the mapping from the paper's interface
stiffnesses to YADE's volumetric law, the shear stiffness per contact, and the time step.

Normal: the volumetric law gives F = kn_yade * V; for faces pressed by an approach u over an area A,
V = A u, so the joint pressure is kn_yade * u: kn_yade [N/m^3] is exactly the interface kn.
Shear: the shear force grows by ks_yade * (shear displacement), so ks_yade is a force per length (N/m):
ks_yade = ks [N/m^3] * depth * (compressed length of the joint), see `compressed_length`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from yadearch.case.config import ArchCase
from yadearch.case.imperfect import amplitudes, imperfect_geometry
from yadearch.case.shape import SIZES, build_arch
from yadearch.errors import CaseError
from yadearch.model import units
from yadearch.model.backfill import Backfill, fill_inertia, fill_surface
from yadearch.model.dispersal import NONE as NOT_DISPERSED
from yadearch.model.dispersal import Dispersal
from yadearch.model.geometry import ArchGeometry
from yadearch.model.loads import ACCELERATION, VERTICAL, LiveLoad


@dataclass(frozen=True)
class ContactStiffness:
    """SI stiffnesses of a joint: `kn` (N/m^3, per unit area), `ks` (N/m^3, per unit area)."""

    kn: float
    ks: float
    tan_friction: float

    @property
    def material_young(self) -> float:
        """`young` to give both YADE materials so that Ip2's harmonic mean young/2 equals kn."""
        return 2.0 * self.kn


def standing_parameters(case: ArchCase) -> str:
    """The parameters that decide whether an arch stands under its own weight, for the message of
    one that does not: the ring's proportions, the friction, the joints' stiffness and any defects."""
    g = case.geometry
    piers = " (2 of them its piers)" if g.piers_mm else ""  # a pier is a block of the arch, not a voussoir
    terms = [f"{g.shape} arch, thickness_mm {g.thickness_mm:g}", f"n_voussoirs {g.n_voussoirs}{piers}"]
    read = [name for name in SIZES.get(g.shape, ()) if not isinstance(getattr(g, name), list)]
    sizes = ", ".join(f"{name} {getattr(g, name):g}" for name in read)
    if sizes:  # the sizes this shape reads (a measured arch's are its joints)
        terms.insert(1, sizes)
    if g.piers_mm:
        terms.append(f"on piers {g.piers_mm[0][0]:g} x {g.piers_mm[0][1]:g} mm")
    terms += [f"friction_deg {case.material.friction_deg:g}", f"kn {case.interface.kn_N_per_mm3:g} N/mm3"]
    defects = [
        f"{name} {value:g}"
        for name, value in vars(case.imperfections).items()
        if isinstance(value, float) and value != 0.0
    ]
    return ", ".join(terms + defects)


def effective_kn_N_per_mm3(case: ArchCase, voussoir_width_mm: float) -> float:
    """Interface kn, optionally in series with the blocks' axial stiffness E / width.

    Two half-blocks of width w/2 on each side of a joint act as springs E/(w/2) per unit area in
    series, i.e. E/w together; rigid blocks (the default) leave kn unchanged.
    """
    kn = case.interface.kn_N_per_mm3
    if not case.material.block_elasticity:
        return kn
    block = case.material.young_MPa / voussoir_width_mm  # MPa/mm = N/mm^3
    return 1.0 / (1.0 / kn + 1.0 / block)


def arch_geometry(case: ArchCase) -> ArchGeometry:
    """The SI geometry of a case, of any shape (`case/shape.py`), built from its voussoirs as they are
    (their dimension errors, `case/imperfect.py`); CaseError if it cannot be built."""
    return imperfect_geometry(case, build_arch(case.geometry))


def contact_stiffness(case: ArchCase, geometry: ArchGeometry) -> ContactStiffness:
    """SI joint stiffnesses for a case; ks keeps the ratio ks/kn of the case. Blocks' elasticity is
    taken over the designed voussoir width, so that dimension errors leave kn alone."""
    designed = geometry if amplitudes(case).perfect_dimensions else build_arch(case.geometry)
    width_mm = units.to_mm(designed.voussoir_width)  # the designed width: no draw changes kn
    kn = units.stiffness_per_volume(effective_kn_N_per_mm3(case, width_mm))
    return ContactStiffness(
        kn=kn, ks=kn * case.interface.ks_over_kn, tan_friction=math.tan(units.radians(case.material.friction_deg))
    )


def compressed_length(offset_from_intrados: float, joint_length: float) -> float:
    """Length of the compressed zone of a joint from where its contact force sits (m).

    A joint that rotates about one edge carries a triangular pressure whose resultant sits at a third
    of the compressed length from that edge, so the length is three times the distance of the
    resultant from the nearer edge, capped at the full joint (uniform or trapezoidal pressure).
    """
    position = min(max(offset_from_intrados, 0.0), joint_length)
    edge_distance = min(position, joint_length - position)
    return min(joint_length, 3.0 * edge_distance)


def critical_timestep(case: ArchCase, geometry: ArchGeometry, stiffness: ContactStiffness) -> float:
    """Critical explicit time step of the stiffest joint mode of a voussoir between its two joints (s).

    A voussoir of width w, thickness t, mass m and polar inertia J sits between two joints of length
    L and area A = L*d: translation stiffness 2*kn*A, rocking stiffness 2*kn*d*L^3/12. The narrowest
    voussoir and the longest joint (L = t for joints normal to the intrados) bound it from below. In
    a chain of such blocks the highest mode reaches sqrt(2) times this single-block frequency;
    dt_crit = 2/omega_max.
    """
    t, d = geometry.thickness, geometry.depth
    w, length = geometry.voussoir_width, geometry.longest_joint
    rho = units.density(case.material.density_g_per_cm3)
    mass = rho * t * w * d
    inertia = mass * (t * t + w * w) / 12.0
    k_translation = 2.0 * stiffness.kn * length * d
    k_rocking = 2.0 * stiffness.kn * d * length**3 / 12.0
    omega = math.sqrt(2.0) * max(math.sqrt(k_translation / mass), math.sqrt(k_rocking / inertia))
    return 2.0 / omega


def runaway_length(case: ArchCase) -> float:
    """The block displacement at a fixed support that means no equilibrium (m): the ring's thickness
    times `numerics.runaway_thickness_ratio`, a bound of the arch's own geometry (docs/numerics.md)."""
    return case.numerics.runaway_thickness_ratio * units.mm(case.geometry.thickness_mm)


VERTICAL_ONLY = {  # the vertical load's parameters, each with its value when unused
    "further_loads": [],
    "load_inclination_deg": 0.0,
    "load_width_mm": 0.0,
    "load_voussoir": 0,
    "load_shape": "uniform",
}
UNIFORM = VERTICAL_ONLY["load_shape"]
MAX_LOAD_RATIO = 100.0  # a further load at most this x the first (whose magnitude is the capacity)


def load_place(case: ArchCase) -> str:
    """Where the vertical load stands, in words: "over voussoir 14" or "at 0.25 of the span", how it
    leans when it does ("leaning 20 deg toward the right") and the fill it disperses through."""
    loads = case.loads
    place = (
        f"over voussoir {loads.load_voussoir}"
        if loads.load_voussoir
        else f"at {loads.load_position_over_span:g} of the span"
    )
    if loads.further_loads:
        rows = ", ".join(f"{ratio:g} x at {offset:+g} mm" for offset, ratio in loads.further_loads)
        place += f", with {len(loads.further_loads)} more ({rows})"
    if loads.load_inclination_deg:
        side = "right" if loads.load_inclination_deg > 0 else "left"
        place += f", leaning {abs(loads.load_inclination_deg):g} deg toward the {side}"
    if loads.load_dispersal != NOT_DISPERSED:
        rule = f"{loads.load_dispersal}, {loads.load_dispersal_deg:g} deg"
        place += f", through {loads.fill_depth_mm:g} mm of fill ({rule})"
    return place


def load_position(case: ArchCase, geometry: ArchGeometry) -> float:
    """The vertical load's centre (m) from the left springing's intrados point: over voussoir
    `load_voussoir` (its extrados's middle) when one is named, else the case's fraction of the span;
    CaseError for a voussoir the arch does not have."""
    loads, n = case.loads, len(geometry.joints) - 1
    if loads.load_voussoir == 0:
        return loads.load_position_over_span * geometry.span
    if not 1 <= loads.load_voussoir <= n:
        raise CaseError(f"loads.load_voussoir must be in [0, {n}] (the arch's voussoirs), got {loads.load_voussoir}")
    ends = geometry.joints[loads.load_voussoir - 1 : loads.load_voussoir + 1]
    return 0.5 * (ends[0].extrados[0] + ends[1].extrados[0]) - geometry.joints[0].intrados[0]


def live_load(case: ArchCase, geometry: ArchGeometry) -> LiveLoad:
    """The case's live load in SI (model.loads): its centre's position from the left springing
    (`load_position`) and the loads that go with it; CaseError for what the load cannot take."""
    loads = case.loads
    if loads.live_load != VERTICAL:
        for name, unset in VERTICAL_ONLY.items():
            if getattr(loads, name) != unset:
                raise CaseError(
                    f"loads.{name} = {getattr(loads, name)!r} is read with loads.live_load = 'vertical' only, got "
                    f"{loads.live_load!r}; set it back to {unset!r}"
                )
    if loads.load_shape != UNIFORM and loads.load_width_mm == 0.0:
        raise CaseError(
            f"loads.load_shape = {loads.load_shape!r} distributes a spread load, but loads.load_width_mm is 0; "
            "give the width (mm) or set load_shape = 'uniform'"
        )
    return LiveLoad(
        loads.live_load,
        dispersal=load_dispersal(case, geometry),
        position=load_position(case, geometry),
        width=units.mm(loads.load_width_mm),
        toward_right=loads.acceleration_toward == "right",
        shape=loads.load_shape,
        inclination=math.radians(loads.load_inclination_deg),
        further=further_loads(case, geometry.span),
        fill_inertia=fill_inertia(geometry, backfill(case)) if loads.live_load == ACCELERATION else (),
    )


def load_dispersal(case: ArchCase, geometry: ArchGeometry) -> Dispersal | None:
    """How the case's vertical load reaches the extrados through its fill (None: it stands on the
    extrados); CaseError for a dispersal without fill or without a vertical load."""
    loads = case.loads
    if loads.load_dispersal == NOT_DISPERSED:
        return None
    if loads.live_load != VERTICAL:
        raise CaseError(f"loads.load_dispersal is read with loads.live_load = 'vertical' only, got {loads.live_load!r}")
    fill = backfill(case)
    if not fill.present:
        raise CaseError(
            f"loads.load_dispersal = {loads.load_dispersal!r} needs a fill to disperse through: loads.fill_depth_mm "
            f"and fill_density_g_per_cm3 > 0, got {loads.fill_depth_mm:g} mm"
        )
    return Dispersal(loads.load_dispersal, math.radians(loads.load_dispersal_deg), fill_surface(geometry, fill))


def further_loads(case: ArchCase, span: float) -> tuple[tuple[float, float], ...]:
    """The case's further loads (`loads.further_loads`) as (offset (m), ratio) on a `span` (m); CaseError
    for a ratio out of (0, MAX_LOAD_RATIO] or an offset longer than the span (one beyond a springing at
    this position goes to the support, as an axle on the approach does)."""
    found = []
    for k, (offset_mm, ratio) in enumerate(case.loads.further_loads, start=1):
        if not 0.0 < ratio <= MAX_LOAD_RATIO:
            raise CaseError(f"loads.further_loads row {k}: ratio must be in (0, {MAX_LOAD_RATIO:g}], got {ratio:g}")
        if abs(units.mm(offset_mm)) > span:  # beyond a springing it stands on the approach (the support)
            raise CaseError(
                f"loads.further_loads row {k}: offset_mm {offset_mm:g} is longer than the span "
                f"({units.to_mm(span):g} mm): that load could never stand on the arch"
            )
        found.append((units.mm(offset_mm), float(ratio)))
    return tuple(found)


def backfill(case: ArchCase) -> Backfill:
    """The case's backfill in SI (model.backfill): its depth over the crown's extrados, unit weight
    (density x g), lateral and passive pressure coefficients; CaseError for a passive coefficient that
    is not above the lateral one or that has no fill to push back."""
    loads = case.loads
    passive = loads.fill_passive_coefficient
    if passive > 0.0 and not passive > loads.fill_lateral_coefficient:
        raise CaseError(
            f"loads.fill_passive_coefficient must be 0 or larger than fill_lateral_coefficient "
            f"({loads.fill_lateral_coefficient:g}), got {passive:g}"
        )
    if passive > 0.0 and not loads.fill_depth_mm > 0.0:
        raise CaseError(
            f"loads.fill_passive_coefficient = {passive:g} needs a fill to push back: loads.fill_depth_mm > 0, got 0"
        )
    return Backfill(
        depth=units.mm(loads.fill_depth_mm),
        unit_weight=units.density(loads.fill_density_g_per_cm3) * case.loading.gravity_m_per_s2,
        lateral_coefficient=loads.fill_lateral_coefficient,
        passive_coefficient=passive,
        passive_displacement=units.mm(loads.fill_passive_displacement_mm),
    )

"""Stiffness mapping from the paper's interface to YADE's volumetric law, and the time step."""

import numpy as np
import pytest
from conftest import DATA

from yadearch.case.config import preset
from yadearch.case.mechanics import (
    arch_geometry,
    compressed_length,
    contact_stiffness,
    critical_timestep,
    effective_kn_N_per_mm3,
)

REFERENCE = DATA / "paper_arch.npz"  # written by the code before arch shapes


def test_kn_maps_one_to_one_and_materials_get_twice_it():
    case = preset("set2")
    k = contact_stiffness(case, arch_geometry(case))
    assert k.kn == pytest.approx(5.2e9)
    assert k.ks == pytest.approx(2.6e9)
    assert k.material_young == pytest.approx(2 * 5.2e9)  # Ip2 takes the harmonic mean: young/2


def test_block_elasticity_in_series_is_off_by_default_and_softens_when_on():
    case = preset("set2")
    width_mm = arch_geometry(case).voussoir_width * 1e3
    assert width_mm == pytest.approx(12.4, abs=0.2)  # paper: "a width of about 12 mm"
    assert effective_kn_N_per_mm3(case, width_mm) == 5.2
    elastic = case.with_overrides({"block_elasticity": True})
    expected = 1 / (1 / 5.2 + width_mm / 941.0)
    assert effective_kn_N_per_mm3(elastic, width_mm) == pytest.approx(expected)


@pytest.mark.parametrize("offset, length", [(0.0, 0.0), (0.004, 0.012), (0.012, 0.024), (0.020, 0.012), (0.030, 0.0)])
def test_compressed_length_follows_the_force_position(offset, length):
    assert compressed_length(offset, 0.024) == pytest.approx(length)


def test_time_step_scales_with_one_over_root_kn():
    s1, s2 = preset("set1"), preset("set2")
    g = arch_geometry(s1)
    dt1 = critical_timestep(s1, g, contact_stiffness(s1, g))
    dt2 = critical_timestep(s2, g, contact_stiffness(s2, g))
    assert dt1 / dt2 == pytest.approx((5.2 / 0.25) ** 0.5)


def test_the_paper_arch_keeps_its_time_step_and_elastic_kn_to_the_last_bit():
    reference = np.load(REFERENCE)
    g = arch_geometry(preset("set2"))
    steps = [critical_timestep(preset(s), g, contact_stiffness(preset(s), g)) for s in ("set1", "set2")]
    assert np.array_equal(steps, reference["critical_timestep_s"])
    elastic = preset("set2").with_overrides({"block_elasticity": True})
    assert contact_stiffness(elastic, g).kn == reference["elastic_kn"]


def test_longer_joints_shorten_the_time_step():
    # vertical joints cross the paper arch's ring obliquely near the springings, where the intrados
    # rises at 62.5 deg: longer than t, shorter than across a straight band, t / sin 27.5 deg
    case = preset("set2")
    vertical = case.with_overrides({"joint_orientation": "vertical"})
    g, gv = arch_geometry(case), arch_geometry(vertical)
    assert 1.9 * g.thickness < gv.longest_joint < g.thickness / np.sin(np.radians(27.5))
    assert (
        critical_timestep(vertical, gv, contact_stiffness(vertical, gv))
        < critical_timestep(case, g, contact_stiffness(case, g)) / 2
    )

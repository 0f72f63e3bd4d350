"""The hand-off to ROSS: `tiltpad.ross.bearing_element` against the command line's `--ross` file, and the
band-sampling warnings of both. Skipped (with the reason) where ROSS cannot be imported."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

import tiltpad
from conftest import CASES

COMPRESSOR = "cases/compressor-bearing.toml"
# A band where the compressor bearing's coefficients are smooth (at preview fidelity pad 1 starts and stops
# floating between about 8050 and 8200 rpm, where they jump: see the jump test).
SPEEDS = [9000, 10000, 11000]

try:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        import ross as rs

    HAVE_ROSS = True
    WHY = ""
except Exception as e:  # ImportError, or a broken optional dependency of ROSS
    HAVE_ROSS = False
    WHY = f"ROSS cannot be imported here ({type(e).__name__}: {e}); pip install 'ross-rotordynamics' 'plotly<6'"

needs_ross = pytest.mark.skipif(not HAVE_ROSS, reason=WHY)


def preview_case():
    case = tiltpad.load_case(str(CASES / "compressor-bearing.toml"))
    case.set("mesh.fidelity", "preview")
    return case


def small_rotor(bearings):
    """A 1 m steel shaft of 0.1 m on two bearings at its ends with one disk in the middle."""
    steel = rs.Material(name="Steel_tp", rho=7810, E=211e9, G_s=81.2e9)
    shaft = [rs.ShaftElement(L=0.125, idl=0.0, odl=0.1, material=steel, shear_effects=True,
                             rotary_inertia=True, gyroscopic=True) for _ in range(8)]
    disk = rs.DiskElement.from_geometry(n=4, material=steel, width=0.07, i_d=0.1, o_d=0.4)
    return rs.Rotor(shaft, [disk], bearings)


def damped_frequencies(rotor, speeds_rad_s):
    return np.array([rotor.run_modal(w, num_modes=8).wd[:4] for w in speeds_rad_s])


@needs_ross
def test_bearing_element_gives_the_damped_frequencies_of_the_cli_file(cli, tmp_path):
    case = preview_case()
    with warnings.catch_warnings():
        warnings.simplefilter("error", tiltpad.BandWarning)  # a smooth band: no warning
        py = tiltpad.ross.bearing_elements(case, nodes=[0, 8], speeds_rpm=SPEEDS, tags="brg")
    assert [b.tag for b in py] == ["brg_0", "brg_8"] and [b.n for b in py] == [0, 8]
    out = tmp_path / "bearings.toml"
    done = cli("coefficients", COMPRESSOR, "--set", 'mesh.fidelity="preview"', "--speed-rpm",
               ",".join(map(str, SPEEDS)), "--node", "0,8", "--tag", "brg", "--ross", str(out))
    assert "warning" not in done.stderr
    import toml

    from_file = [rs.BearingElement.read_toml_data(d) for d in toml.load(out).values()]
    assert [b.tag for b in from_file] == ["brg_0", "brg_8"]
    # The refined band has more samples than the three requested speeds, the same in both.
    np.testing.assert_array_equal(py[0].frequency, from_file[0].frequency)
    assert len(py[0].frequency) > len(SPEEDS)
    speeds = np.array([9500, 10700]) * np.pi / 30
    a = damped_frequencies(small_rotor(py), speeds)
    b = damped_frequencies(small_rotor(from_file), speeds)
    np.testing.assert_allclose(a, b, rtol=1e-12)
    assert np.all(a > 0)
    # One element on its own: the same samples.
    one = tiltpad.ross.bearing_element(case, n=8, speeds_rpm=SPEEDS, tag="b8")
    assert one.n == 8 and one.tag == "b8"
    np.testing.assert_array_equal(one.frequency, py[1].frequency)
    np.testing.assert_array_equal(one.kxx, py[1].kxx)


@needs_ross
def test_a_band_narrower_than_the_analysis_is_warned_as_the_cli_warns(cli):
    case = preview_case()
    with pytest.warns(tiltpad.BandWarning) as record:
        tiltpad.ross.bearing_element(case, n=0, speeds_rpm=[7000, 9000], analysis_speeds_rpm=[4000, 12000],
                                     refine=False)
    messages = [str(w.message) for w in record]
    assert any("7000–9000 rpm" in m and "4000–12000 rpm" in m for m in messages), messages
    done = cli("coefficients", COMPRESSOR, "--set", 'mesh.fidelity="preview"', "--speed-rpm", "7000,9000",
               "--analysis-rpm", "4000:12000", "--no-refine", "--ross", "/dev/null")
    for m in messages:
        assert f"warning: {m}" in done.stderr


def test_coefficient_jumps_are_narrowed_and_warned_as_the_cli_warns(cli):
    """Between 8000 and 9000 rpm (preview) pad 1 starts, then stops floating and the coefficients jump; the
    refined band narrows each jump to one interval of 1/1024 of the band and warns, naming the pad; the CLI
    prints the same."""
    case = preview_case()
    with pytest.warns(tiltpad.BandWarning) as record:
        t = tiltpad.ross.sample(case, speeds_rpm=[8000, 9000])
    messages = [str(w.message) for w in record]
    assert len(messages) >= 1 and all("jump" in m for m in messages), messages
    assert any("pad 1" in m for m in messages), messages
    jumps = [w for w in t.warning_details if w["kind"] == "jump"]
    assert jumps and all(w["to_rpm"] - w["from_rpm"] <= 1000 / 1024 + 1e-9 for w in jumps), jumps
    done = cli("coefficients", COMPRESSOR, "--set", 'mesh.fidelity="preview"', "--speed-rpm", "8000,9000",
               "--ross", "/dev/null")
    assert [line[len("warning: "):] for line in done.stderr.splitlines() if line.startswith("warning: ")] == messages


def test_the_sampling_warnings_without_ross():
    """The band sampler behind both (no ROSS needed): refinement adds checked midpoints; a narrow band warns."""
    case = preview_case()
    t = tiltpad.ross.sample(case, speeds_rpm=SPEEDS)
    assert len(t) >= 5 and t.solves == len(t)
    assert np.all(np.diff(t.speed_rpm) > 0)
    assert set(SPEEDS) <= set(t.speed_rpm.tolist())
    with pytest.warns(tiltpad.BandWarning, match="extrapolates"):
        tiltpad.ross.sample(case, speeds_rpm=[7000, 9000], analysis_speeds_rpm=[4000, 9000], refine=False)
    details = tiltpad.coefficients(case, speeds_rpm=[7000, 9000], analysis_speeds_rpm=[4000, 9000]).warning_details
    assert details == [{"kind": "narrower_than_analysis", "band_from_rpm": 7000.0, "band_to_rpm": 9000.0,
                        "analysis_from_rpm": 4000.0, "analysis_to_rpm": 9000.0}]

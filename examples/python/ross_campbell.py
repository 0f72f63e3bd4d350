"""A ROSS rotor on two tiltpad bearings and its Campbell diagram.

The bearings are `tiltpad.ross.bearing_elements`: the compressor bearing's reduced coefficients over the
analysis' speed band, sampled densely enough for ROSS's spline (with a `tiltpad.BandWarning` where they jump
or where the band misses the analysis range). The rotor is a made-up 1.2 m steel shaft of 0.1 m with two
disks, for illustration.

    python examples/python/ross_campbell.py [--fidelity preview] [--out campbell.png]

Needs ROSS and matplotlib: pip install './python[ross,examples]'.
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

import tiltpad

ROOT = Path(__file__).resolve().parents[2]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--case", default=str(ROOT / "cases" / "compressor-bearing.toml"))
    ap.add_argument("--fidelity", default="preview", choices=["preview", "standard", "reference"])
    ap.add_argument("--from-rpm", type=float, default=3000.0)
    ap.add_argument("--to-rpm", type=float, default=12000.0)
    ap.add_argument("--out", default="campbell.png")
    args = ap.parse_args()

    import ross as rs

    steel = rs.Material(name="Steel_example", rho=7810, E=211e9, G_s=81.2e9)
    n_el = 12
    shaft = [rs.ShaftElement(L=0.1, idl=0.0, odl=0.1016, material=steel) for _ in range(n_el)]
    disks = [rs.DiskElement.from_geometry(n=n, material=steel, width=0.08, i_d=0.1016, o_d=0.45) for n in (4, 8)]

    case = tiltpad.load_case(args.case)
    speeds_rpm = np.linspace(args.from_rpm, args.to_rpm, 10)
    bearings = tiltpad.ross.bearing_elements(
        case,
        nodes=[0, n_el],
        speeds_rpm=speeds_rpm,
        tags="tpjb",
        analysis_speeds_rpm=(args.from_rpm, args.to_rpm),
        fidelity=args.fidelity,
        progress=lambda f, m: print(f"  bearing solves: {m}"),
    )
    print(f"{len(bearings[0].frequency)} samples over {args.from_rpm:.0f}–{args.to_rpm:.0f} rpm")
    rotor = rs.Rotor(shaft, disks, bearings)

    speeds_rad_s = np.linspace(args.from_rpm, args.to_rpm, 25) * np.pi / 30
    campbell = rotor.run_campbell(speeds_rad_s, frequencies=6)
    wd_hz = np.asarray(campbell.wd) / (2 * np.pi)  # (speeds, modes)
    log_dec = np.asarray(campbell.log_dec)

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    rpm = speeds_rad_s * 30 / np.pi
    fig, ax = plt.subplots(1, 2, figsize=(12, 5), constrained_layout=True)
    for k in range(wd_hz.shape[1]):
        sc = ax[0].scatter(rpm, wd_hz[:, k], c=log_dec[:, k], cmap="viridis_r", vmin=0, vmax=1, s=14)
    ax[0].plot(rpm, rpm / 60, "k--", lw=1, label="1×")
    ax[0].set_xlabel("speed [rpm]")
    ax[0].set_ylabel("damped natural frequency [Hz]")
    ax[0].legend()
    fig.colorbar(sc, ax=ax[0], label="log decrement [–]")
    for k in range(log_dec.shape[1]):
        ax[1].plot(rpm, log_dec[:, k], "o-", ms=3, label=f"mode {k + 1}")
    ax[1].axhline(0.1, color="r", lw=1, ls=":", label="API 684 log dec 0.1")
    ax[1].set_xlabel("speed [rpm]")
    ax[1].set_ylabel("log decrement [–]")
    ax[1].set_ylim(-0.5, 3.0)  # overdamped modes (log dec ≫ 1) off the top
    ax[1].legend(fontsize=8)
    for a in ax:
        a.grid(True, alpha=0.3)
    fig.suptitle(f"ROSS rotor on tiltpad bearings ({case.title})")
    fig.savefig(args.out, dpi=110)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()

"""Sweep the preload of the compressor bearing and plot eccentricity, minimum film, peak temperature and the
reduced stiffness and damping against it.

    python examples/python/preload_sweep.py [--fidelity preview] [--out preload.png]

Needs matplotlib (and pandas for the table it prints): pip install './python[examples]'.
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

import tiltpad

ROOT = Path(__file__).resolve().parents[2]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--case", default=str(ROOT / "cases" / "compressor-bearing-tehd.toml"))
    ap.add_argument("--fidelity", default="preview", choices=["preview", "standard", "reference"])
    ap.add_argument("--points", type=int, default=7)
    ap.add_argument("--out", default="preload.png")
    args = ap.parse_args()

    case = tiltpad.load_case(args.case)
    # Preload is one of three ways to give the pads' bore (with clearance_um and bore_radius_mm): replace the
    # case's own by a preload, in one validated edit, before sweeping it.
    case.update({"bearing.pads.bore_radius_mm": None, "bearing.pads.clearance_um": None, "bearing.pads.preload": 0.3})
    preloads = np.linspace(0.0, 0.6, args.points)
    table = tiltpad.sweep(
        case,
        {"bearing.pads.preload": preloads},
        fidelity=args.fidelity,
        progress=lambda f, m: print(f"  {100 * f:5.1f} %  {m}"),
        as_frame=False,
    )
    ok = np.array([e == "" for e in table["error"]])
    for m, e in zip(preloads[~ok], np.array(table["error"])[~ok]):
        print(f"preload {m:.2f} failed: {e}")

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    m = preloads[ok]
    fig, ax = plt.subplots(2, 3, figsize=(12, 6.5), constrained_layout=True)
    ax[0, 0].plot(m, table["eccentricity_ratio"][ok], "o-")
    ax[0, 0].set_ylabel("eccentricity ratio ε [–]")
    ax[0, 1].plot(m, table["h_min_um"][ok], "o-")
    ax[0, 1].set_ylabel("minimum film h_min [µm]")
    t_max = table["t_max_pad_c"][ok]
    if np.all(np.isnan(t_max)):
        t_max = table["t_max_film_c"][ok]
    ax[0, 2].plot(m, t_max, "o-")
    ax[0, 2].set_ylabel("peak temperature T_max [°C]")
    for term in ("kxx", "kyy", "kxy", "kyx"):
        ax[1, 0].plot(m, table[f"{term}_n_per_m"][ok] / 1e6, "o-", label=term)
    ax[1, 0].set_ylabel("reduced stiffness K [MN/m]")
    ax[1, 0].legend()
    for term in ("cxx", "cyy", "cxy", "cyx"):
        ax[1, 1].plot(m, table[f"{term}_ns_per_m"][ok] / 1e3, "o-", label=term)
    ax[1, 1].set_ylabel("reduced damping C [kN·s/m]")
    ax[1, 1].legend()
    ax[1, 2].plot(m, table["friction_power_w"][ok] / 1e3, "o-")
    ax[1, 2].set_ylabel("friction power [kW]")
    for a in ax.flat:
        a.set_xlabel("preload m [–]")
        a.grid(True, alpha=0.3)
    fig.suptitle(f"{case.title}: preload sweep ({args.fidelity})")
    fig.savefig(args.out, dpi=110)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()

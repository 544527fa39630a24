"""Quickstart: the paper's Figure 3 (stick surfaces L and U over theta1 x theta2) from
``pounding.study``, drawn with matplotlib.

    pip install ./crates/pounding-py pandas matplotlib
    python examples/python/quickstart.py [OUT.png]

One geometry (beta1 = beta2 = 60 deg, R1 = R2 = 100 m), mu = 0.25, eps = 0.5: for each of the
four candidate contacts, the lower and upper bounds L <= r <= U of the stick interval of
r = gamma_T/gamma_N over the deck rotations, where the candidate is the first contact (the
other cells are blank), as the CLI's ``figures/surface_*.png``.
"""

import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import pounding  # noqa: E402

SCENARIO = {
    "decks": {"beta1_deg": [60.0], "beta2_deg": [60.0], "R1": [100.0], "R2": [100.0]},
    "impact": {"mu": [0.25], "eps": [0.5]},
    "output": {"figures": False},
}


def main(out: str = "quickstart.png") -> None:
    s = pounding.study(SCENARIO)
    rows = s.rows
    cases = ["deck1-inner", "deck1-outer", "deck2-inner", "deck2-outer"]
    fig = plt.figure(figsize=(11, 9))
    for k, case in enumerate(cases):
        r = rows[rows["case"] == case]
        t1 = np.unique(r["theta1_deg"])
        t2 = np.unique(r["theta2_deg"])
        grid = {name: np.full((len(t2), len(t1)), np.nan) for name in ("lower", "upper")}
        i = np.searchsorted(t1, r["theta1_deg"])
        j = np.searchsorted(t2, r["theta2_deg"])
        first = r["first_contact"].to_numpy()
        for name in grid:
            grid[name][j[first], i[first]] = r[name].to_numpy()[first]
        ax = fig.add_subplot(2, 2, k + 1, projection="3d")
        x, y = np.meshgrid(t1, t2)
        ax.plot_surface(x, y, grid["lower"], color="tab:blue", alpha=0.8, label="L")
        ax.plot_surface(x, y, grid["upper"], color="tab:orange", alpha=0.6, label="U")
        ax.set_title(f"{case}: stick for L <= r <= U")
        ax.set_xlabel("theta1 [deg]")
        ax.set_ylabel("theta2 [deg]")
        ax.set_zlabel("r = gamma_T/gamma_N")
    fig.suptitle("beta1 = beta2 = 60 deg, R1 = R2 = 100 m, mu = 0.25, eps = 0.5 (paper Fig. 3)")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"{len(rows)} rows, {int(rows['first_contact'].sum())} first-contact cells; wrote {out}")


if __name__ == "__main__":
    main(*sys.argv[1:2])

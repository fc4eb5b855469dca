"""The paper's Fig. 3 (the jam map) in numpy + matplotlib: the baseline `cargo bench --bench
render` times beside `jamchart render fig3`, as whole processes.

Same grid (401 x 401 cells: mu 0.1-0.5 linear, theta 10-70 deg log), same closed form (the
corrected Eq. 1: margin mu R_n - R_t, theta_jam = alpha_g + alpha_p + asin(m g sin(alpha_g) / F),
src/statics.rs), same outputs: a 1000 x 950 px PNG (jam and slide regions, the palm's reach, the
boundary theta_jam(mu), the read-off at mu = 0.4) and the cells CSV (mu, theta_deg, region,
margin_n; 7 significant digits). Usage: python fig3.py OUT_DIR
"""

import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

# config/paper.toml
MASS_KG, G, FORCE_N, RADIUS_MM, PALM_LENGTH_MM, MU_READ = 1.0, 9.806, 200.0, 10.0, 150.0, 0.4
NX = NY = 401


def main(out):
    mu = np.linspace(0.1, 0.5, NX)
    theta_deg = 10.0 * (70.0 / 10.0) ** (np.arange(NY) / (NY - 1))
    theta_deg[-1] = 70.0
    th = np.radians(theta_deg)[:, None]
    m = mu[None, :]
    alpha = np.arctan(m)
    # The palm slides: its push leans alpha_p towards the hinge (mu sets both frictions).
    r_t = FORCE_N * np.sin(th - alpha)
    r_n = MASS_KG * G + FORCE_N * np.cos(th - alpha)
    margin = m * r_n - r_t
    reach_deg = np.degrees(2.0 * np.arctan(RADIUS_MM / PALM_LENGTH_MM))
    beyond = np.broadcast_to(theta_deg[:, None] < reach_deg, margin.shape)
    region = np.where(beyond, "beyond_reach", np.where(margin >= 0.0, "jam", "slide"))
    alpha_1 = np.arctan(mu)
    theta_jam = np.degrees(
        2.0 * alpha_1 + np.arcsin(MASS_KG * G * np.sin(alpha_1) / FORCE_N)
    )

    fig, ax = plt.subplots(figsize=(10.0, 9.5), dpi=100)
    codes = np.where(beyond, 2, np.where(margin >= 0.0, 1, 0))
    ax.contourf(mu, theta_deg, codes, levels=[-0.5, 0.5, 1.5, 2.5],
                colors=["white", "#f6c9b5", "#d9d9d9"])
    ax.plot(mu, theta_jam, "k-", label="boundary θ_jam (closed form)")
    t_read = np.interp(MU_READ, mu, theta_jam)
    ax.plot([MU_READ, MU_READ, 0.1], [10.0, t_read, t_read], "k--",
            label=f"read-off at μ = {MU_READ}")
    ax.set_yscale("log")
    ax.set_xlim(0.1, 0.5)
    ax.set_ylim(10.0, 70.0)
    ax.set_xlabel("friction coefficient μ [-]")
    ax.set_ylabel("palm angle θ [deg]")
    ax.set_title("Fig. 3: jamming map over friction μ and palm angle θ")
    pos = ax.secondary_yaxis(
        "right",
        functions=(lambda t: RADIUS_MM / np.tan(np.radians(np.clip(t, 1e-3, 179.0)) / 2.0),
                   lambda x: np.degrees(2.0 * np.arctan(RADIUS_MM / np.maximum(x, 1e-9)))),
    )
    pos.set_ylabel("disc position x [mm]")
    ax.legend(loc="upper left")
    fig.savefig(os.path.join(out, "fig3.png"))
    plt.close(fig)

    # One row per cell, x fastest: mu, theta_deg, region, margin_n.
    cols = [
        np.char.mod("%.7g", np.broadcast_to(m, margin.shape)).ravel(),
        np.char.mod("%.7g", np.broadcast_to(theta_deg[:, None], margin.shape)).ravel(),
        region.ravel(),
        np.char.mod("%.7g", margin).ravel(),
    ]
    with open(os.path.join(out, "fig3.csv"), "w") as f:
        f.write("mu,theta_deg,region,margin_n\n")
        f.write("\n".join(",".join(row) for row in zip(*cols)))
        f.write("\n")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else ".")

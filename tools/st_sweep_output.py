"""Output of a wall-bounce St sweep (examples/wall_bounce and examples/liggghts): the CSV
table and the e/e_d-against-St plot with Legendre's law exp(-35/St) drawn over the points."""
import csv
import math


def write_csv(path, rows):
    with open(path, "w", newline="") as fh:
        writer = csv.DictWriter(fh, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)


def plot(path, rows, label, marker="o", color="tab:orange", extra=None):
    """extra: optional (column, label, marker, color) of a second series from the same rows."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4))
    st_line = [10 ** (k / 50) for k in range(25, 176)]
    ax.semilogx(st_line, [math.exp(-35 / s) for s in st_line], "k-",
                label="Legendre et al. (2005): exp(-35/St)")
    ax.semilogx([r["St"] for r in rows], [r["e_over_ed"] for r in rows], marker, color=color,
                label=label)
    if extra:
        column, extra_label, extra_marker, extra_color = extra
        ax.semilogx([r["St"] for r in rows], [r[column] for r in rows], extra_marker,
                    color=extra_color, label=extra_label)
    ax.set_xlabel("Stokes number St = (2/9) rho_p R U / mu_f")
    ax.set_ylabel("e / e_d")
    ax.set_ylim(-0.05, 1.05)
    ax.set_title("Wet particle-wall restitution")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(loc="upper left", fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)

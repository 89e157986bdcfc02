"""Plots for case-based tests: numerical profiles against an exact or
reference solution, saved as PNG (matplotlib, Agg backend: no display).

    import plots
    plots.compare_profiles(
        "tests/run/V2_n400/profiles.png",
        [("rho", "rho [kg/m^3]"), ("u", "u [m/s]"), ("p", "p [Pa]")],
        runs=[("impactFoam, 400 cells", x, {"rho": rho, "u": u, "p": p})],
        reference=("exact", xe, {"rho": rhoe, "u": ue, "p": pe}),
        title="water-air shock tube, t = 240 us")

Plotting never decides a test: failures to plot are reported and ignored.
"""
import os
import sys

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except Exception as e:  # pragma: no cover - matplotlib missing
    plt = None
    _IMPORT_ERROR = e

_MARKERS = ["o", "s", "^", "v", "D", "x"]


def compare_profiles(path, quantities, runs, reference=None, title="",
                     xlabel="x [m]", xlim=None):
    """One panel per quantity (stacked vertically).

    quantities  list of (key, axis label)
    runs        list of (label, x, {key: values}) drawn as markers/lines
    reference   (label, x, {key: values}) drawn as a black line, or None
    Returns the path written, or None (with a message on stderr) if the
    figure could not be made."""
    if plt is None:
        sys.stderr.write("plots: matplotlib unavailable (%s)\n"
                         % _IMPORT_ERROR)
        return None
    try:
        os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
        n = len(quantities)
        fig, axes = plt.subplots(n, 1, figsize=(8, 2.6 * n + 0.6),
                                 sharex=True, squeeze=False)
        for ax, (key, label) in zip(axes[:, 0], quantities):
            if reference is not None and key in reference[2]:
                ax.plot(reference[1], reference[2][key], "k-", lw=1.2,
                        label=reference[0], zorder=3)
            for i, (rlabel, x, values) in enumerate(runs):
                if key not in values:
                    continue
                few = len(x) <= 250
                ax.plot(x, values[key],
                        marker=_MARKERS[i % len(_MARKERS)] if few else None,
                        ms=3, lw=0.8 if few else 1.0,
                        ls="-" if not few else ":", label=rlabel, zorder=2)
            ax.set_ylabel(label)
            ax.grid(True, lw=0.3)
            if xlim is not None:
                ax.set_xlim(*xlim)
        axes[0, 0].legend(fontsize=8, loc="best")
        axes[-1, 0].set_xlabel(xlabel)
        if title:
            fig.suptitle(title)
        fig.tight_layout()
        fig.savefig(path, dpi=110)
        plt.close(fig)
        return path
    except Exception as e:
        sys.stderr.write("plots: could not write %s: %s\n" % (path, e))
        return None


def convergence(path, resolutions, errors, title="", ylabel="relative L1 error"):
    """Log-log plot of errors against the number of cells.

    resolutions  list of cell counts
    errors       {label: list of errors (same order as resolutions)}"""
    if plt is None:
        return None
    try:
        os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
        fig, ax = plt.subplots(figsize=(5.5, 4.2))
        for i, (label, errs) in enumerate(errors.items()):
            ax.loglog(resolutions, errs, marker=_MARKERS[i % len(_MARKERS)],
                      label=label)
        # first-order slope for orientation
        r0, e0 = resolutions[0], max(max(v) for v in errors.values())
        ax.loglog(resolutions, [e0 * r0 / r for r in resolutions], "k--",
                  lw=0.8, label="slope -1")
        ax.set_xlabel("cells")
        ax.set_ylabel(ylabel)
        ax.grid(True, which="both", lw=0.3)
        ax.legend(fontsize=8)
        if title:
            ax.set_title(title)
        fig.tight_layout()
        fig.savefig(path, dpi=110)
        plt.close(fig)
        return path
    except Exception as e:
        sys.stderr.write("plots: could not write %s: %s\n" % (path, e))
        return None

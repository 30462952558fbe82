"""The two log-log panels of the refinement studies (refine_study.py, re_entrant_study.py):
an error against DOFs and against run time, a uniform and an adaptive line per series."""


def plot_error_against_cost(series, ylabel, title, path):
    """series: {label: (style, [(dofs, seconds, error), ...])}, style as matplotlib's line
    keywords; writes the figure to `path`."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figure, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for label, (style, points) in series.items():
        axes[0].loglog([p[0] for p in points], [p[2] for p in points], label=label, **style)
        axes[1].loglog([p[1] for p in points], [p[2] for p in points], label=label, **style)
    for axis, xlabel in zip(axes, ["DOFs", "run time [s]"]):
        axis.set_xlabel(xlabel)
        axis.set_ylabel(ylabel)
        axis.grid(True, which="both", alpha=0.3)
    axes[0].legend(fontsize=8)
    figure.suptitle(title)
    figure.tight_layout()
    figure.savefig(path, dpi=120)
    print(f"\nplot: {path}")


def line_style(uniform, color):
    """Uniform runs: circles and a solid line; adaptive runs: squares and a dashed one."""
    return dict(marker="o" if uniform else "s", linestyle="-" if uniform else "--", color=color)

"""The horizon planner against the step-by-step controller on a payload that arrives at a known step.

A pre-bent four-segment chain (``Segment(1, 1, 1, (1.04, 0.96))`` x 4) moves its tip up by 0.2 over five steps and
holds it; at step 7 a compressive payload ``F = (-0.08, 0)`` arrives. Every rest length may change by at most 0.04
per step and every step needs a stability margin of 0.05. Under the payload the arm needs stiffer springs than it
has: more change than one step allows. The step-by-step controller (``plan_preloads``) sees the payload only at
step 7 and goes infeasible from there on; the receding horizon (``plan_preloads(..., horizon=10)``) sees it
coming and stiffens the arm during the steps before it, on target throughout.

Run ``python docs/horizon_example.py``: writes ``docs/img/horizon_payload.png`` and prints the numbers.
"""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import tensegrity_opt as to  # noqa: E402
from tensegrity_opt.analyses.design.preload_control import PreloadController, plan_preloads  # noqa: E402

OUT = Path(__file__).resolve().parent / "img" / "horizon_payload.png"
M = to.Manipulator.uniform(4, 1.0, 1.0, 1.0, (1.04, 0.96))
K, ARRIVES, PAYLOAD, RATE, MARGIN, HORIZON = 14, 7, 0.08, 0.04, 0.05, 10


def case():
    q0 = PreloadController(M).q
    tip0 = M.tip(q0)
    targets = np.array([tip0 + np.array([-0.1, 0.2]) * min(k, 5) / 5 for k in range(K)])
    loads = np.zeros((K, 2))
    loads[ARRIVES:, 0] = -PAYLOAD
    return targets, loads


def main() -> dict:
    targets, loads = case()
    sbs = plan_preloads(M, targets, loads=loads, rate_limit=RATE, dt=1.0, margin=MARGIN)
    hz = plan_preloads(M, targets, loads=loads, rate_limit=RATE, dt=1.0, margin=MARGIN, horizon=HORIZON)
    rest0 = np.column_stack([M.L1_0, M.L2_0])
    steps = np.arange(K)
    err_s = np.linalg.norm(np.asarray(sbs.tip) - targets, axis=1)
    err_h = hz.tip_error
    R_s, R_h = sbs.commands, hz.commands
    fig, ax = plt.subplots(1, 3, figsize=(14.0, 4.2), constrained_layout=True)
    for a in ax:
        a.axvspan(ARRIVES - 0.5, K - 0.5, color="0.92", zorder=0)
        a.set_xlabel("step")
    ax[0].semilogy(steps, np.maximum(err_s, 1e-12), "o-", color="tab:red", label="step by step (plan_preloads)")
    ax[0].semilogy(steps, np.maximum(err_h, 1e-12), "s-", color="tab:blue", label=f"receding horizon N = {HORIZON}")
    ax[0].axhline(1e-6, color="black", ls=":", lw=1.0, label="on target (1e-6 max b)")
    ax[0].set_ylabel("tip error |tip - target|")
    ax[0].set_title("tip error (shaded: payload F = (-0.08, 0) on)")
    ax[0].legend(fontsize=8)
    for i in range(M.n):
        ax[1].plot(steps, R_h[:, i, 0], "-", color=f"C{i}", label=f"segment {i + 1}" if i < M.n else None)
        ax[1].plot(steps, R_s[:, i, 0], ":", color=f"C{i}")
    # the rate envelope of the horizon plan's commands: each step within +- RATE of the one before
    prev = np.vstack([rest0[None], R_h[:-1]])
    for i in range(M.n):
        ax[1].fill_between(steps, prev[:, i, 0] - RATE, prev[:, i, 0] + RATE, color=f"C{i}", alpha=0.12, lw=0)
    ax[1].set_ylabel("rest length $L_{1,0}$ (solid: horizon, dotted: step by step)")
    ax[1].set_title(f"commands and their rate envelope (+- {RATE} per step)")
    ax[1].legend(fontsize=8)
    ax[2].plot(steps, np.where(sbs.feasible, sbs.margin, np.nan), "o-", color="tab:red", label="step by step")
    ax[2].plot(steps, hz.margin, "s-", color="tab:blue", label=f"receding horizon N = {HORIZON}")
    ax[2].axhline(MARGIN, color="black", ls=":", lw=1.0, label=f"required margin {MARGIN}")
    ax[2].set_yscale("log")
    ax[2].set_ylabel("stability margin (torque / rad)")
    ax[2].set_title("margin (step by step: feasible steps only)")
    ax[2].legend(fontsize=8)
    fig.suptitle("A payload arriving at step 7: the horizon plan stiffens the arm ahead of it")
    OUT.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(OUT, dpi=110)
    moves = np.abs(np.diff(np.concatenate([rest0[None], R_h]), axis=0)).max(axis=(1, 2))
    numbers = {
        "step_by_step_infeasible_steps": [int(k) for k in steps[~np.asarray(sbs.feasible)]],
        "step_by_step_max_tip_error": float(err_s.max()),
        "horizon_status": hz.status, "horizon_infeasible_steps": [int(k) for k in steps[~hz.feasible]],
        "horizon_max_tip_error": float(err_h.max()),
        "horizon_min_margin_under_payload": float(hz.margin[ARRIVES:].min()),
        "horizon_largest_move_per_step": [round(float(v), 4) for v in moves], "rate": RATE,
        "horizon_seconds": round(hz.seconds, 2), "figure": str(OUT),
    }
    for k, v in numbers.items():
        print(f"{k}: {v}")
    return numbers


if __name__ == "__main__":
    main()

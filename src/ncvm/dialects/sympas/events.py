"""The events a task can enable (§6.4, L1548-1610): when each is active.

EVEO, EVDNR, EVLSH and EVUI follow the card's digital inputs (machine file ``sympas.inputs``), EVLSS the
soft limits, EVMPE the position error. The task polls them (task.py).
"""

from __future__ import annotations

from .axes import AxisState

EVENT_INPUTS = {"EVEO": ("EO",), "EVDNR": ("DR",), "EVLSH": ("LSL", "LSR"), "EVUI": ("UI",)}


def input_active(ax: AxisState, inp: dict) -> bool:
    """Whether input ``inp`` of the machine file is active on axis ``ax`` (its level, or inverted)."""
    level = bool(ax.digi >> (int(inp["bit"]) - 1) & 1)
    return level != bool(inp.get("active_low", False))


def event_active(card, name: str, t: float) -> bool:
    """Whether event ``name`` is active at ``t``: a task with a handler for it runs the handler."""
    if name in EVENT_INPUTS:
        funcs = EVENT_INPUTS[name]
        for inp in card.inputs:
            if inp.get("function") in funcs:
                ax = card.axes[card.names.index(inp["axis"])]
                active = input_active(ax, inp)
                if name == "EVDNR":
                    active = not active  # drive not ready: the DR input became inactive
                if active:  # a handler runs on an outside input (ncvm translate marks it)
                    card.canon.frozen(f"event {name}: digital input {inp['axis']}.{inp['bit']} "
                                      f"({inp['function']}) active", None)
                    return True
        return False
    if name == "EVLSS":
        if card.cfg.soft_limit_reaction not in ("TOM", "SMA"):
            return False
        for ax in card.axes:
            p = card.mpos(ax, t)
            if p < ax.q["sll"] or p > ax.q["slr"]:
                return True
            if ax.limit_stop and (p <= ax.q["sll"] + 1e-6 or p >= ax.q["slr"] - 1e-6):
                return True  # stopped on the limit by the soft-limit reaction (softlimits.py)
        return False
    if name == "EVMPE":
        return any(ax.closed and abs(ax.poserr) > ax.q["mpe"] for ax in card.axes)
    return False


def events_follow_motion(card, tk) -> bool:
    """Whether an event ``tk`` has enabled can change while the axes move: EVLSS (an axis crossing its
    soft limit) when the soft-limit reaction raises it. The input events change with timed actions only."""
    return ("EVLSS" in tk.enabled and card.cfg.soft_limit_reaction in ("TOM", "SMA")
            and any(a.move is not None for a in card.axes))

"""The rules a block's words keep before it runs, from the control's profile: one function of each modal group
(the profile's rows, its M groups), and the control's own rules (``Profile.block_rules``: rs274's for ``iso``).

A block that breaks one has no one meaning (``G90 G91 X5``: absolute or incremental?); the control refuses it,
and so does ncvm, instead of keeping the last of two words silently. A front end applies :func:`block_refusal`
once per block where it decodes the block (din's reading pass, the CPL block compiler, the SINUMERIK reader),
and ``ncvm check`` the same function, so run and check agree. In the kernel only the dwell rows apply their
rule (to the dwell blocks they run), and LinuxCNC's G53 is held against the modal motion, which no text shows.
"""

from __future__ import annotations

from . import CYCLE, DWELL, ISO_DWELL_HINT, MOTION, Profile, dwell_alone, lone_dwell_fault

#: the code of a block with two functions of one group, or two functions that both take the axis words
CONFLICT = "NC015"


def group_conflict(groups: dict, codes) -> tuple | None:
    """(first, second, group) of two codes of one group in ``codes`` (``groups``: code -> group), or None."""
    seen: dict = {}
    for c in codes:
        group = groups.get(c)
        if group is not None:
            if group in seen:
                return seen[group], c, group
            seen[group] = c
    return None


def g_conflict(profile: Profile, g) -> tuple | None:
    """(message, the second code) for two G functions of one modal group of ``profile`` in ``g``, or None. The
    controls' dialects refuse it with their own code (CPL040, SIN001), din with NC015."""
    both = group_conflict(profile.g_groups, g) if len(g) > 1 else None
    if both is None:
        return None
    first, second, group = both
    name = f"{group} ({profile.groups[group]})" if group in profile.groups else group
    return (f"G{first:g} and G{second:g} in one block: two functions of G group {name}; the control runs one "
            "function of each group", second)


def block_refusal(profile: Profile, g, m, words, axes) -> tuple | None:
    """(code, message, address, value) of the first rule the block (its G codes ``g``, M codes ``m`` and
    ``words``; ``axes`` the machine's axis names) breaks -- ``address`` and ``value`` name the word to point
    at -- or None."""
    both = g_conflict(profile, g)
    if both is not None:
        return (CONFLICT, both[0], "G", both[1])
    both = group_conflict(profile.m_groups, m) if len(m) > 1 and profile.m_groups else None
    if both is not None:
        first, second, group = both
        return (CONFLICT, f"M{first} and M{second} in one block: two functions of M group {group}; the control "
                "runs one function of each group", "M", second)
    if g and (found := dwell_time(profile, g, words, axes)) is not None:
        return found
    for rule in profile.block_rules:
        if (found := rule(profile, g, m, words)) is not None:
            return found
    return None


# -- rs274's rules (the iso profile) -----------------------------------------------------------------------
#: the G functions of group 0 that take the block's axis words as their values (rs274's "covets axes")
AXIS_USERS = frozenset((10, 92))
#: the G functions that read a D word (rs274: "D word with no G41, G41.1, G42, G42.1 ... or G96 to use it")
D_USERS = frozenset((41, 41.1, 42, 42.1, 96))


def _motion_codes(profile: Profile, g) -> list:
    """The codes of ``g`` that move (the motion rows and the canned cycles; not G80, G98, G99)."""
    dispatch = profile.dispatch
    return [x for x in g if (run := dispatch.get(x, (None,))[0]) == MOTION or (run == CYCLE and x not in (80, 98, 99))]


def axis_users(profile: Profile, g, m, words) -> tuple | None:
    """rs274: "Cannot use two g codes that both use axis values" (G92 X0 G0: set position or move?), and "Must
    use g0 or g1 with g53" for a motion code of the block."""
    motion = _motion_codes(profile, g) if len(g) > 1 else ()
    users = [x for x in g if x in AXIS_USERS]
    if users and motion:
        return (CONFLICT, f"G{users[0]:g} and G{motion[0]:g} in one block: both take the axis words as their "
                "values (rs274 refuses the block)", "G", motion[0])
    if 53 in g and any(x not in (0, 1) for x in motion):
        bad = next(x for x in motion if x not in (0, 1))
        return ("NC009", f"G53 (machine coordinates) with G{bad:g}: a move in machine coordinates is G0 or G1 "
                "(rs274: \"Must use g0 or g1 with g53\")", "G", 53)
    return None


def d_word(profile: Profile, g, m, words) -> tuple | None:
    """rs274: a D word needs G41, G41.1, G42, G42.1 or G96 in its block; elsewhere no function reads it, and
    ``G1 Y5 D2`` under G41 would keep cutting with the radius it had."""
    if "D" in words and not D_USERS.intersection(g):
        return ("NC009", f"D{words['D']:g} with no G41, G41.1, G42, G42.1 or G96 in its block to use it (rs274 "
                "refuses it; a new cutter radius is selected with G41/G42 D<n>)", "D", None)
    return None


def dwell_time(profile: Profile, g, words, axes) -> tuple | None:
    """A G4 block whose time is X or F is a block of its own (``lone_dwell_fault``, as the kernel's dwell rows
    check it); rs274's G4 P dwells and then moves."""
    dwell = next((x for x in g if profile.dispatch.get(x, (None,))[0] == DWELL), None)
    if dwell is None:
        return None
    iso = profile.dispatch[dwell][1] is not dwell_alone
    if iso and "P" in words:
        return None
    fault = lone_dwell_fault(profile, dwell, words, g, axes, iso, ISO_DWELL_HINT if iso else "")
    return ("NC009", fault, "G", dwell) if fault else None

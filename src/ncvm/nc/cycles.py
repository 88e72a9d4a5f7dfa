"""Canned cycles G73, G74, G81-G89 of the ISO profile, as LinuxCNC's rs274ngc runs them (interp_cycles.cc).

A cycle block positions in the selected plane at rapid, goes down to the R plane, runs the cycle's moves
along the plane's normal axis and comes back to the clearance height: the R plane under G99, under G98
the height the tool had when the cycles began (the *initial level*, kept while cycle follows cycle), or R
when that lies lower. G80 and the cycles are motion modes: a block with axis words repeats the cycle at
the new position until G80 or G0-G3; R, the depth (Z in G17), P and Q are kept from the last cycle block.
In G91, X and Y are increments repeated L times, R counts from the initial level and Z from R.

The moves are rs274's, call for call and in the same float operations, so a differential test
(tests/nc/test_canned_cycles.py) compares them with ``rs274 -g``. The errors are rs274's, under NC009.
"""

from __future__ import annotations

from .canon import Src
from .kernel import PLANES

#: the cycles (motion modes besides G0-G3 and G80)
CYCLES = frozenset((73, 74, 81, 82, 83, 84, 85, 86, 87, 88, 89))
#: the G codes the canned cycles take over from the kernel: the cycles, G80, G98 and G99
CODES = CYCLES | {80, 98, 99}
#: G73 retracts by this much after each peck, G83 comes back down to this far above the last depth (mm):
#: rs274's G83_RAPID_DELTA, 0.010 inch in either unit (LinuxCNC 2.9)
PECK_CLEARANCE = 0.254
_DWELL_G = (82, 86, 88, 89)
#: the cycles that use P, Q, I, J, K; in another cycle's block such a word is an error, as in rs274
#: ("Q word with no G5, G10, G64, G73, G76, G83"), never dropped silently (P of G74/G84: the tap's dwell)
_WORD_USERS = (("P", frozenset((*_DWELL_G, 74, 84))), ("Q", frozenset((73, 83))), ("I", frozenset((87,))),
               ("J", frozenset((87,))), ("K", frozenset((87,))))


class CannedCycles:
    """The cycles' modal state on one kernel (``kernel.canned``): retract mode and the kept words."""

    codes = CODES

    def __init__(self, peck_clearance: float = PECK_CLEARANCE):
        self.peck_clearance = peck_clearance
        self.retract_to_r = True  # G99 at power-on, as rs274
        self.r = 0.0  # the last R word (mm), the last depth word, P (s), Q (mm), I J K (mm) of G87
        self.depth = 0.0
        self.p = 0.0
        self.q = 0.0
        self.ijk = (0.0, 0.0, 0.0)
        self.initial = 0.0  # the initial level: the normal axis's programmed position when the cycles began

    def block(self, k, motion: int, explicit: bool, words: dict, src: Src) -> None:
        """One block in motion mode ``motion`` (a cycle or G80); ``explicit``: the block names the G code."""
        an, bn, cn, _i, _j = PLANES[k.plane]
        names = [n for n in words if n in k.axis_of]
        if motion == 80:
            if names:
                k.fault("NC009", f"axis word {names[0]} with G80: no motion mode is active (program G0, G1, ...)",
                        src)
            k.motion = 80
            return
        previous = k.motion
        if not explicit and not names:
            return  # nothing to drill: a block with F, S, M ... only
        if k.spindle_bound:
            k.spindle_update(src)  # G95: the feed for the spindle speed now
        if k.feed <= 0.0:
            k.fault("NC006", k.no_feed_message(motion), src)
        if cn not in k.axis_of or an not in k.axis_of or bn not in k.axis_of:
            k.fault("NC009", f"G{motion} in plane G{k.plane} needs axes {an}, {bn} and {cn}", src)
        same = previous == motion
        if not same and "R" not in words:
            k.fault("NC009", f"G{motion}: R clearance plane unspecified in the cycle", src)
        if not same and cn not in words:
            k.fault("NC009", f"G{motion}: {cn} value (the depth) unspecified in the cycle", src)
        a, b, c = k.axis_of[an], k.axis_of[bn], k.axis_of[cn]
        scale = k.scale
        r_word = words["R"] * scale if "R" in words else self.r
        depth_word = words[cn] * scale if cn in words else self.depth
        here = k.prog
        current_cc = here[c]
        if previous not in CYCLES:
            self.initial = current_cc
        old_cc = self.initial
        if k.absolute:
            inc_a = inc_b = 0.0
            r, cc = r_word, depth_word
            aa = words[an] * scale if an in words else here[a]
            bb = words[bn] * scale if bn in words else here[b]
        else:
            inc_a = words[an] * scale if an in words else 0.0
            inc_b = words[bn] * scale if bn in words else 0.0
            r = r_word + old_cc
            cc = r + depth_word
            aa, bb = here[a], here[b]
        if r < cc:
            k.fault("NC009", f"G{motion}: R plane below the depth {cn} in the cycle", src)
        repeats = int(words.get("L", 1))
        if repeats < 1:
            k.fault("NC009", f"G{motion}: L{repeats}: a cycle runs at least once (L1 or more)", src)
        body = self._body(k, motion, same, words, src)
        if old_cc < r:
            self._go(k, a, b, c, here[a], here[b], r, True, src)
            old_cc = current_cc = r
        clear = r if self.retract_to_r else old_cc
        for n in range(repeats):
            aa += inc_a
            bb += inc_b
            if n == 0 and current_cc > r:
                self._go(k, a, b, c, aa, bb, current_cc, True, src)
                self._go(k, a, b, c, aa, bb, r, True, src)
            else:
                self._go(k, a, b, c, aa, bb, clear, True, src)
                if clear > r:
                    self._go(k, a, b, c, aa, bb, r, True, src)
            body(k, (a, b, c), aa, bb, r, clear, cc)
        k.motion = motion
        self.r, self.depth = r_word, depth_word

    def _body(self, k, motion: int, same: bool, words: dict, src: Src):
        """The cycle's own moves, as ``body(k, axes, aa, bb, r, clear, bottom)``, after its words are checked."""
        for letter, users in _WORD_USERS:
            if letter in words and motion not in users:
                k.fault("NC009", f"G{motion}: {letter} word with no cycle that uses it "
                        f"({', '.join(f'G{u}' for u in sorted(users))} do)", src)
        if motion in _DWELL_G or motion in (74, 84):
            if "P" in words:
                self.p = words["P"]
            elif not same and motion in _DWELL_G:
                k.fault("NC009", f"G{motion}: dwell time P word missing", src)
        if motion in (73, 83):
            if "Q" in words:
                self.q = words["Q"] * k.scale
            elif not same:
                k.fault("NC009", f"G{motion}: Q word (the peck depth) missing", src)
            if self.q <= 0.0:
                k.fault("NC009", f"G{motion}: the peck depth Q must be positive", src)
        if motion in (74, 84, 86, 87, 88):
            self._spindle_check(k, motion, src)
        if motion == 87:
            if k.plane != 17:
                k.fault("NC004", "G87 (back boring) outside plane G17 is not supported by ncvm", src)
            if not same and not all(w in words for w in "IJK"):
                k.fault("NC009", "G87: I, J and K words needed", src)
            self.ijk = tuple(words[w] * k.scale if w in words else v for w, v in zip("IJK", self.ijk))
        go, dwell, p = self._go, self._dwell, self.p

        def g81(k, ax, aa, bb, r, clear, bottom):
            go(k, *ax, aa, bb, bottom, False, src)
            if motion == 82:
                dwell(k, p, src)
            go(k, *ax, aa, bb, clear, True, src)

        def g83(k, ax, aa, bb, r, clear, bottom):
            q, delta = self.q, self.peck_clearance
            depth = r - q
            while depth > bottom:
                go(k, *ax, aa, bb, depth, False, src)
                if motion == 83:
                    go(k, *ax, aa, bb, r, True, src)
                go(k, *ax, aa, bb, depth + delta, True, src)
                depth = depth - q
            go(k, *ax, aa, bb, bottom, False, src)
            go(k, *ax, aa, bb, clear, True, src)

        def g84(k, ax, aa, bb, r, clear, bottom):
            k.canon.tapping(motion, src)
            turning = k.spindle_dir
            go(k, *ax, aa, bb, bottom, False, src)
            k.turn_spindle(0, src)
            k.turn_spindle(-turning, src)
            dwell(k, p, src)
            go(k, *ax, aa, bb, clear, False, src)
            k.turn_spindle(0, src)
            k.turn_spindle(turning, src)

        def g85(k, ax, aa, bb, r, clear, bottom):
            go(k, *ax, aa, bb, bottom, False, src)
            if motion == 85:
                go(k, *ax, aa, bb, r, False, src)
                go(k, *ax, aa, bb, clear, True, src)
                return
            dwell(k, p, src)  # G89
            go(k, *ax, aa, bb, clear, False, src)

        def g86(k, ax, aa, bb, r, clear, bottom):
            turning = k.spindle_dir
            go(k, *ax, aa, bb, bottom, False, src)
            dwell(k, p, src)
            k.turn_spindle(0, src)
            if motion == 86:
                go(k, *ax, aa, bb, clear, True, src)
            else:  # G88: the program stops; the operator takes the tool out by hand to the clearance height
                k.stopped_at = "G88"
                k.canon.stop("G88", src)
                prog = list(k.prog)
                prog[ax[2]] = clear
                k.place(tuple(p + o for p, o in zip(prog, k.offset_vec)), prog)
            k.turn_spindle(turning, src)

        def g87(k, ax, aa, bb, r, clear, bottom):
            turning = k.spindle_dir
            i, j, kk = self.ijk
            middle = kk if k.absolute else bottom + kk
            oa, ob = aa + i, bb + j
            go(k, *ax, oa, ob, r, True, src)
            k.turn_spindle(0, src)
            go(k, *ax, oa, ob, bottom, True, src)
            go(k, *ax, aa, bb, bottom, True, src)
            k.turn_spindle(turning, src)
            go(k, *ax, aa, bb, middle, False, src)
            go(k, *ax, aa, bb, bottom, False, src)
            k.turn_spindle(0, src)
            go(k, *ax, oa, ob, bottom, True, src)
            go(k, *ax, oa, ob, clear, True, src)
            go(k, *ax, aa, bb, clear, True, src)
            k.turn_spindle(turning, src)

        return {81: g81, 82: g81, 73: g83, 83: g83, 74: g84, 84: g84, 85: g85, 89: g85, 86: g86, 88: g86,
                87: g87}[motion]

    @staticmethod
    def _spindle_check(k, motion: int, src: Src) -> None:
        """G74 taps left-hand (spindle M4), G84 right-hand (M3); G86-G88 need the spindle turning."""
        want = {74: -1, 84: 1}.get(motion)
        if k.spindle_dir == 0 or (want is not None and k.spindle_dir != want):
            turning = {74: "counter-clockwise (M4)", 84: "clockwise (M3)"}.get(motion, "(M3 or M4)")
            k.fault("NC009", f"G{motion} needs the spindle turning {turning}", src)

    @staticmethod
    def _go(k, a: int, b: int, c: int, aa: float, bb: float, cc: float, rapid: bool, src: Src) -> None:
        prog = list(k.prog)
        prog[a], prog[b], prog[c] = aa, bb, cc
        k.straight_to(prog, rapid, src)

    @staticmethod
    def _dwell(k, seconds: float, src: Src) -> None:
        k.machine.clock.advance(seconds)
        k.canon.dwell(seconds, src)

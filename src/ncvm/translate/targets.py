"""The controls a translation is written for: one table row each, the words that differ between them.

The writer (:mod:`ncvm.translate.writer`) is the same for every target; a :class:`Target` says how each
thing is spelled on that control: comments, zero offset selection, tool length, dwell, probing, full
turns of a helix, program end and wrapper. None in a field means the control has no such word: the
translation stops with a clear error naming the block that needs it.
"""

from __future__ import annotations

import textwrap
import unicodedata
from dataclasses import dataclass, field


@dataclass(frozen=True)
class Target:
    """How one control spells the words the translation writes."""

    name: str
    title: str
    #: a comment line
    comment: str
    #: the modal words set before the first move (units mm, absolute, plane, feed per minute, no compensation)
    preamble: str
    #: the name of each zero offset selection of the program ("G54".."G59") on this control
    work_offsets: dict[str, str]
    #: tool length compensation from offset number {n}, and its cancellation
    tool_length_on: str
    tool_length_off: str
    #: tool length compensation subtracted (G44) from offset number {n}, None: the control has none
    tool_length_minus: str | None
    #: a move in machine coordinates (G53), one block; and whether the control keeps the tool length in it
    machine_move: str
    machine_move_keeps_tool: bool
    #: a dwell of {s} seconds
    dwell: str
    #: a probe move ({axes} the target, {feed} the feed words), None: the control has no probe move
    probe: str | None
    #: the probe move where the simulated probe made no contact and the program went on
    probe_no_contact: str | None
    #: the word of extra full turns {n} of a helix, None: written as separate arcs
    turns: str | None
    #: a thread of constant lead ({axes} the end point, {lead} the path distance per revolution), None: the
    #: control has no such word (a thread written as G1 would not follow the spindle)
    thread: str | None
    #: an operator message
    message: str
    program_end: str
    #: the path control: modal exact stop, continuous path, continuous path within a corner tolerance {tol}
    #: (None: the control's continuous path takes no tolerance), exact stop of one block (None: the modal
    #: exact stop around its move), and the mode the control is in after the preamble (nothing written while
    #: it holds: every preamble selects G64, since a control keeps the mode the last program left, M2 or not)
    path_exact: str = "G61"
    path_continuous: str = "G64"
    path_tolerance: str | None = None
    exact_stop_block: str | None = None
    path_power_on: str = "continuous"
    #: what the control's continuous path without a tolerance does (the header says it beside the tolerance the
    #: simulation blended corners within: a bare G64 leaves the new control's own, as a zero offset is its own)
    bare_continuous: str = "the control's own corner rounding, a setting of that control"
    #: selected for ``--frame machine`` (the header says that it must be all zero), with no tool length where
    #: the preamble does not cancel it (840D: D0)
    machine_frame: str = "G54"
    #: the first and last line of the file (the tape wrapper), empty: none
    wrapper: str = ""
    #: the address letters of axes this control has
    axes: str = "XYZABCUVW"
    #: characters a comment may not hold, with their replacement
    comment_escapes: dict[str, str] = field(default_factory=dict)
    #: the tool offset number is an edge of the active tool (840D: D1 of T2 is not D1 of T1): the header names the tool
    edge_of_tool: bool = False
    #: Fanuc-style input: every length, angle and dwell word with a decimal point (``X10.``), S an integer
    decimal_point: bool = False
    #: the machine move is a positioning at rapid traverse whatever the motion mode (Fanuc-style G53): a fed
    #: one is refused
    machine_move_rapid: bool = False
    #: the longest line the control reads (rs274ngc: 252 characters, tried with rs274; "Command too long"
    #: from 253 on); the others are given the same bound
    max_line: int = 252

    #: the character set of the file: rs274 reads UTF-8 comments and messages (tried); the 840D and ISO
    #: targets get ASCII (:func:`ascii_text`)
    charset: str = "ascii"

    def escape(self, text: str) -> str:
        """``text`` without the characters that would end this control's comment or message, in the
        control's character set."""
        for bad, good in self.comment_escapes.items():
            text = text.replace(bad, good)
        return text if self.charset != "ascii" or text.isascii() else ascii_text(text)

    def note(self, text: str) -> str:
        """``text`` as a comment of this control: several lines where one would be too long to read."""
        return "\n".join(self.fit(self.comment, self.escape(text)))

    def fit(self, form: str, text: str) -> list[str]:
        """``form`` filled with ``text`` in lines of at most :attr:`max_line` characters (split between words)."""
        room = self.max_line - len(form.format(""))
        if len(text) <= room:
            return [form.format(text)]
        return [form.format(part) for part in textwrap.wrap(text, room, break_long_words=True)]


#: German letters as written without umlauts; other accented letters lose the accent (NFKD)
_TRANSLITERATION = str.maketrans({"ä": "ae", "ö": "oe", "ü": "ue", "Ä": "Ae", "Ö": "Oe", "Ü": "Ue", "ß": "ss"})


def ascii_text(text: str) -> str:
    """``text`` in ASCII: umlauts transliterated (Wärme -> Waerme), accents dropped (é -> e), any other
    character written as ``<U+65E5>``, never a silent ``?`` (docs/translate.md)."""
    text = unicodedata.normalize("NFKD", text.translate(_TRANSLITERATION))
    return "".join(c if c.isascii() else "" if unicodedata.combining(c) else f"<U+{ord(c):04X}>" for c in text)


_PARENS = {"(": "[", ")": "]"}
#: ISO: ``%`` is the tape's end-of-record mark, read as such also inside a comment
_ISO_ESCAPES = {**_PARENS, "%": "pct"}
_ISO_OFFSETS = {f"G{n}": f"G{n}" for n in range(54, 60)}

LINUXCNC = Target(
    name="linuxcnc", title="LinuxCNC (rs274ngc)", comment="({})",
    preamble="G21 G90 G17 G94 G40 G49 G80 G64", work_offsets=_ISO_OFFSETS,
    tool_length_on="G43 H{n}", tool_length_off="G49", tool_length_minus=None,
    machine_move="G53", machine_move_keeps_tool=False,
    dwell="G4 P{s}", probe="G38.2 {axes}{feed}", probe_no_contact="G38.3 {axes}{feed}", turns=" P{n}", message="(MSG, {})",
    thread="G33 {axes} K{lead}",
    program_end="M2", path_tolerance="G64 P{tol}", comment_escapes=_PARENS, charset="utf-8",
    bare_continuous="no tolerance at all (best possible speed)")

#: SINUMERIK 840D: G54-G57 are settable zero offsets, G58/G59 programmable ones: the program's G58/G59
#: selections go to the next settable ones, G505/G506; the tool length comes with the D number
SINUMERIK_840D = Target(
    name="sinumerik840d", title="SINUMERIK 840D", comment="; {}",
    preamble="G71 G90 G17 G94 G40 G64", work_offsets={"G54": "G54", "G55": "G55", "G56": "G56", "G57": "G57",
                                                 "G58": "G505", "G59": "G506"},
    tool_length_on="D{n}", tool_length_off="D0", tool_length_minus=None, edge_of_tool=True,
    machine_move="SUPA", machine_move_keeps_tool=True,
    dwell="G4 F{s}", probe="MEAS=1 G1 {axes}{feed}", probe_no_contact="MEAS=1 G1 {axes}{feed}", turns=" TURN={n}", message='MSG("{}")',
    thread=None,
    program_end="M30", path_exact="G60", exact_stop_block="G9",
    bare_continuous="the control's own continuous-path mode (how it slows at corners is its machine data)",
    machine_frame="G500 D0", comment_escapes={'"': "'", "\n": " "})

#: plain ISO / Fanuc style: the tape wrapper %, G43 H, dwell in seconds as X; no standard probe move
ISO = Target(
    name="iso", title="ISO / Fanuc style", comment="({})",
    preamble="G21 G90 G17 G94 G40 G49 G80 G64", work_offsets=_ISO_OFFSETS,
    tool_length_on="G43 H{n}", tool_length_off="G49", tool_length_minus="G44 H{n}",
    machine_move="G53", machine_move_keeps_tool=False,
    dwell="G4 X{s}", probe=None, probe_no_contact=None, turns=None, message="({})", thread=None,
    program_end="M30", exact_stop_block="G09", wrapper="%", comment_escapes=_ISO_ESCAPES, decimal_point=True,
    machine_move_rapid=True)

TARGETS = {t.name: t for t in (LINUXCNC, SINUMERIK_840D, ISO)}

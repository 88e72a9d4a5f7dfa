"""The profiles by name (a machine file's ``[din] profile`` names one)."""

from __future__ import annotations

from .iso import ISO
from .sinumerik8xx import SINUMERIK8XX
from .typ3osa import TYP3OSA

PROFILES = {p.name: p for p in (ISO, TYP3OSA, SINUMERIK8XX)}

"""The simulated controller: machine data model, machine files, permanent store, file root."""

from .config import load_machine, machine_from_dict
from .model import Axis, Machine, PlcImage, SimClock, Tool
from .store import Store

__all__ = ["Axis", "Machine", "PlcImage", "SimClock", "Store", "Tool", "load_machine", "machine_from_dict"]

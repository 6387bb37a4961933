"""Sofa.constants: names of keys as key events carry them (``event['key']``).

    from Sofa.constants import *
    if event['key'] == Key.uparrow: ...
"""
from . import Key  # noqa: F401

__all__ = ["Key"]

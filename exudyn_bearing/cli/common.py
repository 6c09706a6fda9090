"""Shared pieces of the sub-commands: the parser class, number parsing, tables."""
from __future__ import annotations

import argparse
import math

from ..data import catalog

__all__ = ["Parser", "finite_float", "print_table", "BEARING_HELP"]

#: Help text of a bearing argument.
BEARING_HELP = f"catalogue name ({', '.join(catalog)}) or a JSON file"


def finite_float(text):
    try:
        v = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number, got {text!r}") from None
    if not math.isfinite(v):
        raise argparse.ArgumentTypeError(f"must be finite, got {text!r}")
    return v


class Parser(argparse.ArgumentParser):
    """One-line errors (no usage dump), exit status 2."""

    def error(self, message):
        self.exit(2, f"exudyn-bearing: error: {message} (see --help)\n")


def print_table(rows):
    width = max(len(k) for k, _ in rows)
    for k, v in rows:
        if isinstance(v, float):
            v = f"{v:.6g}"
        print(f"{k:<{width}}  {v}")

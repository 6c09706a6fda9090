"""The example gallery's hooks (docs/conf.py configures sphinx-gallery and names them).

The short examples of docs/examples_src/ run in the build; the scenarios of scenarios/ are shown from their
source without running, with what the documented run printed where the repository keeps it
(scenarios/printed/<script>.txt, written by scenarios/_printed.py's ``recording``).
"""
import warnings
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PRINTED = ROOT / "scenarios" / "printed"
#: Folder of the generated scenario pages under docs/ (sphinx_gallery_conf's gallery_dirs).
SCENARIO_PAGES = "scenarios"

_saved_filters = []


def example_warnings_are_errors(gallery_conf, fname, when):
    """sphinx-gallery ``reset_modules`` hook: a warning in a gallery example (a run too short to be steady, a
    step above the stable estimate, ...) raises, which fails the example and with it the build, as -W does
    for Sphinx's own warnings. The filters before the example are put back after it."""
    if when == "before":
        _saved_filters.append(warnings.filters[:])
        warnings.simplefilter("error")
    elif _saved_filters:
        warnings.filters[:] = _saved_filters.pop()


def stored_output_block(stem, depth=1):
    """The reST that shows ``scenarios/printed/<stem>.txt`` (included from a page ``depth`` folders below
    docs/), '' when the repository keeps no output of that scenario."""
    path = PRINTED / f"{stem}.txt"
    if not path.is_file():
        return ""
    command = path.read_text().splitlines()[0].lstrip("$ ")
    rel = "../" * (depth + 1) + f"scenarios/printed/{stem}.txt"
    return (f".. rubric:: Stored output\n\nWhat ``{command}`` printed in its documented run "
            f"(``scenarios/printed/{stem}.txt``; the build does not run it):\n\n"
            f".. literalinclude:: {rel}\n   :language: text\n\n")


def stored_output(app, docname, source):
    """Sphinx ``source-read`` hook: a scenario's generated page gets its stored output after the code, before
    sphinx-gallery's download links."""
    folder, _, stem = docname.partition("/")
    if folder != SCENARIO_PAGES or "/" in stem:
        return
    block = stored_output_block(stem)
    anchor = f".. _sphx_glr_download_{SCENARIO_PAGES}_{stem}.py:"
    if block and anchor in source[0]:
        source[0] = source[0].replace(anchor, block + anchor, 1)

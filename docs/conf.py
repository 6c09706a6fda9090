"""Sphinx configuration of the exudyn_bearing documentation.

Build: ``pip install -e ".[docs]" && python -m sphinx -W -b html docs docs/_build/html``
(warnings, broken references included, are errors; the last step of .ci/run; docs/developer.md has the time
it takes). The pages are Markdown (MyST): README's guides, docs/theory/*.md as they are,
the validation report from the outputs the validation scripts stored (nothing
reruns here), the API reference from the numpydoc docstrings, and a sphinx-gallery of examples: the short
scripts of docs/examples_src/ run in the build (their output and figures shown), the scenarios of
scenarios/ rendered from their source with the output the repository stores (not run).
"""
import os
import re
import sys
import types
from pathlib import Path

DOCS = Path(__file__).resolve().parent
ROOT = DOCS.parent
sys.path.insert(0, str(DOCS))
sys.path.insert(0, str(ROOT))

import _gallery  # noqa: E402  (docs/_gallery.py: the example gallery's hooks)
import _pages  # noqa: E402  (docs/_pages.py: the generated pages)

# autosummary's recursion imports every module of the package, exudyn_bearing/__main__.py too, which runs the
# command line on the build's own arguments: a stand-in keeps it from running (it has nothing to document)
sys.modules.setdefault("exudyn_bearing.__main__", types.ModuleType("exudyn_bearing.__main__"))

project = "exudyn_bearing"
author = "exudyn_bearing authors"
copyright = "exudyn_bearing authors, BSD-3-Clause"  # noqa: A001
try:
    from importlib.metadata import version as _version

    release = _version("exudyn-bearing")
except Exception:  # noqa: BLE001  (built from a source tree without the install)
    release = "0.1.0"

extensions = [
    "myst_parser",
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.napoleon",
    "sphinx.ext.mathjax",
    "sphinx_gallery.gen_gallery",
]
source_suffix = {".md": "markdown", ".rst": "restructuredtext"}
root_doc = "index"
# examples_src/ holds the gallery's sources (its GALLERY_HEADER.rst goes into the generated examples/index.rst)
exclude_patterns = ["_build", "Thumbs.db", ".DS_Store", "examples_src"]

# MyST: anchors for headings (docs/theory links to "page.md#heading"), $...$ maths, ::: fences
myst_heading_anchors = 4
myst_enable_extensions = ["dollarmath", "colon_fence", "deflist"]

# API reference: numpydoc-style docstrings through napoleon
autosummary_generate = True
# each object documented once, where it is defined: the package's re-exports (exudyn_bearing.BallBearing, ...)
# are not documented again under the re-exporting module
autodoc_default_options = {"members": True, "undoc-members": False, "show-inheritance": False,
                           "ignore-module-all": True}
autodoc_member_order = "bysource"
autodoc_typehints = "description"
napoleon_numpy_docstring = True
napoleon_google_docstring = False
napoleon_use_ivar = True  # "Attributes" sections as fields: a dataclass field is not described twice

# Not errors: a module name that two layers share (``kinematics`` in physics/ and solvers/quasistatic/) written
# as a relative reference in a docstring (Sphinx takes the first; the text names the layer), and numpydoc's
# "References" lists, whose entries are not all cited inline. Every other warning, broken links included,
# fails the build (-W).
suppress_warnings = ["ref.python", "ref.footnote"]

nitpicky = False  # docstrings name numpy/scipy/exudyn types without intersphinx (no network in the build)



# The gallery (sphinx-gallery): docs/examples_src/*.py, a few seconds each, are run and shown with their output
# (docs/examples/, generated); scenarios/*.py, minutes each, are rendered from their source without running
# (docs/scenarios/, generated), with the output the repository stores (_gallery.stored_output). Generated
# files stay under docs/ (.gitignore).
sphinx_gallery_conf = {
    "examples_dirs": ["examples_src", "../scenarios"],
    "gallery_dirs": ["examples", "scenarios"],
    "filename_pattern": re.escape(f"{os.sep}examples_src{os.sep}"),  # run these; the scenarios are not run
    "ignore_pattern": r"(^|[/\\])(_[^/\\]*|__init__)\.py$",  # scenarios/_printed.py is a helper
    "within_subsection_order": "FileNameSortKey",
    "run_stale_examples": True,  # their numbers always come from the code being documented
    "download_all_examples": False,
    "notebook_extensions": set(),  # no notebooks: a scenario reads its command line (argparse), not a kernel's
    "write_computation_times": False,  # each example's page states its own run time
    "reset_modules": ("matplotlib", "_gallery.example_warnings_are_errors"),  # names: a config value Sphinx can cache
    "reset_modules_order": "both",
    "show_signature": False,
}

html_theme = "pydata_sphinx_theme"
html_title = "exudyn_bearing"
html_static_path = []
html_theme_options = {
    "navigation_with_keys": False,
    "show_toc_level": 2,
}



def _escape_bars(app, what, name, obj, options, lines):
    """The docstrings are plain text with |x| for an absolute value (and no reST substitutions): escape
    the bars that do not start a table row, so that docutils reads them as text."""
    for i, line in enumerate(lines):
        row = line.strip()
        table_row = row.startswith(("+-", "+=")) or (row.startswith("|") and row.endswith("|") and row.count("|") > 2)
        if "|" in line and not table_row:
            lines[i] = line.replace("|", "\\|")


def _plain_data_and_field_ends(app, what, name, obj, options, lines):
    """A module-level dict or list (``data.catalog``) has no docstring of its own: drop the one of its
    builtin type. After the fields napoleon writes (``:param x: ...``), a paragraph of free text needs
    the blank line reST asks for."""
    if what in ("data", "attribute") and type(obj).__module__ == "builtins" and lines \
            and "\n".join(lines).strip() == (type(obj).__doc__ or "").strip():
        lines[:] = []
        return
    i = 1
    while i < len(lines):
        prev, line = lines[i - 1], lines[i]
        in_field = prev.startswith(":") or (prev.startswith(" ") and any(x.startswith(":") for x in lines[:i]))
        if in_field and line and not line[0].isspace() and not line.startswith(":") and prev.strip():
            lines.insert(i, "")
        i += 1


def _free_text_after_parameters(app, what, name, obj, options, lines):
    """A paragraph of free text written at the end of a numpydoc "Parameters" or "Attributes" section
    comes out of napoleon as one empty ``:param LINE:`` (``:ivar LINE:``) per line, without a type:
    put it back as a paragraph."""
    typed = {re.match(r":(?:type|vartype) ([^:]+):", line).group(1) for line in lines
             if re.match(r":(?:type|vartype) ([^:]+):", line)}

    def bogus(line):
        m = re.match(r":(?:param|ivar) (.+?):\s*$", line)
        return bool(m) and ": " not in m.group(1) and m.group(1) not in typed

    i = 0
    while i < len(lines):
        if bogus(lines[i]):
            j = i
            while j < len(lines) and bogus(lines[j]):
                j += 1
            text = " ".join(re.match(r":(?:param|ivar) (.+?):\s*$", x).group(1) for x in lines[i:j])
            lines[i:j] = ["", text, ""]
            i += 3
        else:
            i += 1


def setup(app):
    app.connect("source-read", _gallery.stored_output)
    app.connect("autodoc-process-docstring", _free_text_after_parameters)
    app.connect("autodoc-process-docstring", _escape_bars)
    app.connect("autodoc-process-docstring", _plain_data_and_field_ends)


# the generated pages (validation, scenarios, defaults stub) are written before the build reads the sources
_pages.write_all(DOCS, ROOT)
if os.environ.get("EXUDYN_BEARING_DOCS_LIST_ONLY"):
    raise SystemExit(0)

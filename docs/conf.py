"""Sphinx configuration of the exudyn_bearing documentation.

Build: ``pip install -e ".[docs]" && python -m sphinx -W -b html docs docs/_build/html``
(warnings, broken references included, are errors; .ci/docs runs it).
The pages are Markdown (MyST): README's guides, docs/theory/*.md as they are,
the validation report from the outputs the validation scripts stored (nothing
reruns here), the API reference from the numpydoc docstrings.
"""
import os
import sys
from pathlib import Path

DOCS = Path(__file__).resolve().parent
ROOT = DOCS.parent
sys.path.insert(0, str(DOCS))
sys.path.insert(0, str(ROOT))

import _pages  # noqa: E402  (docs/_pages.py: the generated pages)

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
]
source_suffix = {".md": "markdown", ".rst": "restructuredtext"}
root_doc = "index"
exclude_patterns = ["_build", "Thumbs.db", ".DS_Store"]

# MyST: anchors for headings (docs/theory links to "page.md#heading"), $...$ maths, ::: fences
myst_heading_anchors = 4
myst_enable_extensions = ["dollarmath", "colon_fence", "deflist"]

# API reference: numpydoc-style docstrings through napoleon
autosummary_generate = True
autodoc_default_options = {"members": True, "undoc-members": False, "show-inheritance": False}
autodoc_member_order = "bysource"
autodoc_typehints = "description"
napoleon_numpy_docstring = True
napoleon_google_docstring = False

nitpicky = False  # docstrings name numpy/scipy/exudyn types without intersphinx (no network in the build)

html_theme = "pydata_sphinx_theme"
html_title = "exudyn_bearing"
html_static_path = []
html_theme_options = {
    "navigation_with_keys": False,
    "show_toc_level": 2,
}

# the generated pages (validation, scenarios, defaults stub) are written before the build reads the sources
_pages.write_all(DOCS, ROOT)
if os.environ.get("EXUDYN_BEARING_DOCS_LIST_ONLY"):
    raise SystemExit(0)

"""The documentation's example gallery (sphinx-gallery, docs/conf.py): the short examples of docs/examples_src/
run as the build runs them (warnings are errors there) and each draws one figure and prints a table; every
example and scenario has the title its page needs and names pages that exist; the scenarios' stored outputs
are shown from where the generated pages live."""
import ast
import importlib
import re
import runpy
import sys
import warnings

import pytest

import exudyn_bearing as eb

from conftest import ROOT

sys.path.insert(0, str(ROOT / "docs"))
import _gallery  # noqa: E402

EXAMPLES = sorted((ROOT / "docs" / "examples_src").glob("plot_*.py"))
SCENARIOS = sorted(p for p in (ROOT / "scenarios").glob("*.py") if not p.name.startswith("_"))


def _docstring(path):
    return ast.get_docstring(ast.parse(path.read_text()), clean=False)


def _title(doc):
    """The reST title of a docstring: its first line, underlined by '=' of the same length (sphinx-gallery
    makes it the page's title; an underline of another length is a docutils warning, which -W fails)."""
    first, underline = doc.strip("\n").splitlines()[:2]
    return first if underline == "=" * len(first) else None


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_example_runs_without_warnings_and_draws_one_figure(path, capsys):
    import matplotlib

    matplotlib.use("agg")
    import matplotlib.pyplot as plt

    plt.close("all")
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # as in the build (docs/_gallery.py)
        runpy.run_path(str(path), run_name="__main__")
    figures = plt.get_fignums()
    axes = [ax for n in figures for ax in plt.figure(n).axes]
    plt.close("all")
    assert len(figures) == 1 and all(ax.has_data() for ax in axes)
    lines = [x for x in capsys.readouterr().out.splitlines() if x.strip()]
    assert len(lines) >= 4  # a header and rows


def test_there_are_examples_and_each_says_what_it_shows_and_where_it_is_explained():
    assert len(EXAMPLES) >= 5
    for path in EXAMPLES:
        doc = _docstring(path)
        assert _title(doc), path.name
        pages = re.findall(r":doc:`(/[\w/]+)`", doc)
        assert pages, f"{path.name} names no page that explains it"
        for page in pages:
            assert (ROOT / "docs" / f"{page[1:]}.md").is_file(), (path.name, page)


def test_the_examples_link_the_objects_of_the_public_names():
    # ":func:`eb.name <module.path.name>`": the reference page of the object documented where it is defined
    seen = set()
    for path in EXAMPLES:
        for public, target in re.findall(r":func:`eb\.(\w+) <([\w.]+)>`", _docstring(path)):
            module, _, name = target.rpartition(".")
            obj = getattr(importlib.import_module(module), name) if module != "exudyn_bearing" else \
                getattr(eb, name)
            assert obj is getattr(eb, public), target
            seen.add(public)
    assert {"solve_quasistatic", "rating_life", "bearing_coefficients", "simulate"} <= seen


def test_each_scenario_has_a_page_title_and_its_command_as_a_literal_block():
    for path in SCENARIOS:
        doc = _docstring(path)
        title = _title(doc)
        assert title, path.name
        # argparse's description is the docstring's first line: the title, not its underline
        assert doc.split("\n")[0] == title
        # the command as a literal block ("::"), so that "--option" is not set as a dash
        assert re.search(rf"::\n\n    python scenarios/{path.name}", doc), path.name


def test_a_scenario_page_shows_its_stored_output_from_the_generated_folder():
    printed = sorted((ROOT / "scenarios" / "printed").glob("*.txt"))
    assert printed
    for txt in printed:
        assert (ROOT / "scenarios" / f"{txt.stem}.py").is_file(), txt.name
        block = _gallery.stored_output_block(txt.stem)
        include = re.search(r"\.\. literalinclude:: (\S+)", block).group(1)
        # included from docs/scenarios/<stem>.rst
        assert (ROOT / "docs" / _gallery.SCENARIO_PAGES / include).resolve() == txt.resolve()
        assert txt.read_text().splitlines()[0].lstrip("$ ") in block
        anchor = f".. _sphx_glr_download_scenarios_{txt.stem}.py:"
        source = [f"Title\n=====\n\n.. code-block:: Python\n\n   main()\n\n{anchor}\n\nfooter\n"]
        _gallery.stored_output(None, f"scenarios/{txt.stem}", source)
        assert source[0].index("Stored output") < source[0].index(anchor)
    # a scenario without a stored output, and pages of other folders, are left as they are
    unstored = next(p.stem for p in SCENARIOS if not (ROOT / "scenarios" / "printed" / f"{p.stem}.txt").exists())
    for docname in (f"scenarios/{unstored}", f"examples/{printed[0].stem}"):
        source = [f".. _sphx_glr_download_scenarios_{unstored}.py:\n"]
        _gallery.stored_output(None, docname, source)
        assert "Stored output" not in source[0]


def test_the_generated_gallery_is_ignored_by_git():
    ignored = (ROOT / ".gitignore").read_text().split()
    assert {"docs/examples/", "docs/scenarios/"} <= set(ignored)
    assert (ROOT / "docs" / "examples_src" / "GALLERY_HEADER.rst").is_file()
    assert (ROOT / "scenarios" / "GALLERY_HEADER.rst").is_file()

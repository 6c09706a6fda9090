"""The documentation's page per validation script (docs/_pages.py): assembled from the script's docstring and
what it printed into validation/REPORT.md, every report section on the page of the script that printed it."""
import re
import sys

from conftest import ROOT

sys.path.insert(0, str(ROOT / "docs"))
import _pages  # noqa: E402


def test_every_script_has_a_page_with_its_report_sections(tmp_path):
    _pages.validation_pages(tmp_path, ROOT)
    scripts = sorted(p for p in (ROOT / "validation").glob("*/*.py") if not p.name.startswith("_"))
    pages = {p.relative_to(tmp_path / "validation").as_posix() for p in (tmp_path / "validation").glob("*/*.md")}
    assert pages == {f"{p.parent.name}/{p.stem}.md" for p in scripts}
    # every section of the report that names its command is on that script's page, figures resolved from docs/
    report = (ROOT / "validation" / "REPORT.md").read_text()
    sections = [(b.split("\n", 1)[0].strip(), re.search(r"^Command: `python validation/(\w+)/(\w+)\.py", b, flags=re.M))
                for b in re.split(r"^## ", report, flags=re.M)[1:]]
    assert len(sections) > 30 and all(m for _t, m in sections)
    for title, m in sections:
        folder, stem = m.groups()
        page = (tmp_path / "validation" / folder / f"{stem}.md").read_text()
        assert f"### {title}" in page
        for link in re.findall(r"\]\(([^)]+\.png)\)", page):
            assert (ROOT / "docs" / "validation" / folder / link).resolve().is_file(), link
    page = (tmp_path / "validation" / "performance" / "bench_levels.md").read_text()
    assert "## In the report's run" in page and "quasistatic, exact Hertz" in page
    assert _pages.docstring(ROOT / "validation" / "performance" / "bench_levels.py").split("\n")[0] in page

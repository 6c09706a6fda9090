"""Pages of the documentation written from the repository at build time (docs/conf.py calls
:func:`write_all`): one page per folder of validation/ and per validation script, and the validation
report. Nothing here runs a simulation: the pages are assembled from the scripts' docstrings,
tests/test_readme_claims.py's claims and the report the validation scripts last wrote
(validation/REPORT.md, its figures in validation/report_figures/). The examples and the scenarios are
sphinx-gallery's (docs/conf.py, docs/_gallery.py).

The generated files are listed in .gitignore (docs/validation/)."""
import ast
import re
from pathlib import Path

#: Folders of validation/ and what they hold (validation/README.md says the same).
FOLDERS = {
    "published": "Published and measured cases",
    "consistency": "Consistency between the solvers",
    "performance": "Performance: benchmarks and profiles",
    "studies": "Studies: step limits, convergence, what the models do",
}


def docstring(path):
    """The module docstring of ``path`` ('' without one)."""
    return ast.get_docstring(ast.parse(path.read_text(), str(path))) or ""


def first_sentence(text):
    """The docstring's first paragraph, on one line."""
    return " ".join(text.split("\n\n")[0].split())


def claims_by_script(root):
    """{script file name: [(claim text, page that says it), ...]} from tests/test_readme_claims.py's
    CLAIMS (the numbers of README and the docs pages and the command that printed each)."""
    tree = ast.parse((root / "tests" / "test_readme_claims.py").read_text())
    claims = next(ast.literal_eval(node.value) for node in tree.body
                  if isinstance(node, ast.Assign) and getattr(node.targets[0], "id", "") == "CLAIMS")
    pages = [root / "README.md", *sorted(q for q in (root / "docs").rglob("*.md")
                                         if "_build" not in q.parts and q.parent.name != "validation")]
    texts = {q.relative_to(root).as_posix(): " ".join(q.read_text().split()) for q in pages}
    out = {}
    for text, _printed, command in claims:
        name, flat = Path(command.split()[1]).name, " ".join(text.split())
        where = next((page for page, body in texts.items() if flat in body), "?")
        if (flat, where) not in out.setdefault(name, []):
            out[name].append((flat, where))
    return out


def report_sections(root):
    """{script file name: [section title of validation/REPORT.md that names it]}."""
    report = (root / "validation" / "REPORT.md").read_text()
    out = {}
    for block in re.split(r"^## ", report, flags=re.M)[1:]:
        title = block.splitlines()[0].strip()
        for name in set(re.findall(r"([A-Za-z0-9_]+\.py)", block)):
            out.setdefault(name, []).append(title)
    return out


def report_blocks(root):
    """{script path under validation/ (e.g. "performance/bench_levels.py"): [(title, body), ...]}: the
    sections of validation/REPORT.md, each under the script its ``Command:`` line runs (a section is what
    that script printed in the report's run, with the report's words around it)."""
    report = (root / "validation" / "REPORT.md").read_text()
    out = {}
    for block in re.split(r"^## ", report, flags=re.M)[1:]:
        title, _, body = block.partition("\n")
        m = re.search(r"^Command: `python validation/([\w/]+\.py)", body, flags=re.M)
        if m:
            out.setdefault(m.group(1), []).append((title.strip(), body.strip()))
    return out


def _report_images(body, depth):
    """``body`` with the report's figure paths (report_figures/x.png, relative to validation/) made relative
    to a page ``depth`` folders below docs/."""
    up = "../" * (depth + 1)
    return re.sub(r"\]\((report_figures/[^)]+)\)", lambda m: f"]({up}validation/{m.group(1)})", body)


def script_page(path, rel, blocks, claims):
    """The page of one validation script: its docstring, the numbers of README and the docs it backs, and
    what it printed in the report's run (its sections of validation/REPORT.md, figures included)."""
    lines = [f"# {path.name}", "", f"`python {rel}`", "", "```text", docstring(path) or "(no docstring)", "```", ""]
    if claims:
        lines += ["## Numbers it backs", "",
                  "Quoted in README and these pages (tests/test_readme_claims.py ties each to the report):", ""]
        lines += [f"- \u201c{_md_escape(claim)}\u201d ({where})" for claim, where in claims] + [""]
    if blocks:
        lines += ["## In the report's run", "",
                  "What it printed when `python validation/make_report.py` last ran it (validation/REPORT.md; the "
                  "build does not rerun it).", ""]
        for title, body in blocks:
            lines += [f"### {title}", "", re.sub(r"^(#+) ", r"#\1 ", _report_images(body, 2), flags=re.M), ""]
    return "\n".join(lines).rstrip() + "\n"


def _md_escape(text):
    return text.replace("|", "\\|").replace("*", "\\*").replace("_", "\\_")


def validation_pages(docs, root):
    """docs/validation/<folder>.md for each folder of validation/ (and 'unsorted' for scripts
    still at the top level) with a page per script (docs/validation/<folder>/<script>.md:
    :func:`script_page`), docs/validation/report.md (the report, included)."""
    vdir = root / "validation"
    target = docs / "validation"
    target.mkdir(exist_ok=True)
    for old in [*target.glob("*.md"), *target.glob("*/*.md")]:  # generated whole: no page of a script gone
        old.unlink()
    claims, sections, blocks = claims_by_script(root), report_sections(root), report_blocks(root)
    folders = {name: title for name, title in FOLDERS.items() if (vdir / name).is_dir()}
    top = sorted(p for p in vdir.glob("*.py") if p.name != "make_report.py" and not p.name.startswith("_"))
    if top:
        folders["unsorted"] = "Scripts not yet sorted into a folder"
    for name, title in folders.items():
        scripts = top if name == "unsorted" else sorted(p for p in (vdir / name).glob("*.py")
                                                        if not p.name.startswith("_"))
        (target / name).mkdir(exist_ok=True)
        lines = [f"# {title}", "", f"Scripts of `validation/{'' if name == 'unsorted' else name + '/'}`: what each "
                 "checks (its docstring's first paragraph), the sections of the [report](report.md) it feeds and the "
                 "numbers of README and these pages it backs (tests/test_readme_claims.py ties each to the "
                 "report). Each script's page holds its docstring and what it printed in the report's run.", ""]
        for p in scripts:
            rel = p.relative_to(root).as_posix()
            (target / name / f"{p.stem}.md").write_text(
                script_page(p, rel, blocks.get(rel[len("validation/"):], []), claims.get(p.name, [])))
            lines += [f"## {p.name}", "", f"`python {rel}` ([its page]({name}/{p.stem}.md))", "",
                      _md_escape(first_sentence(docstring(p))) or "(no docstring)", ""]
            if sections.get(p.name):
                lines += ["Report sections: " + "; ".join(f"*{_md_escape(s)}*" for s in sections[p.name]) + ".", ""]
            for claim, where in claims.get(p.name, []):
                lines += [f"- backs \u201c{_md_escape(claim)}\u201d ({where})"]
            lines += [""]
        lines += ["```{toctree}", ":hidden:", "", *(f"{name}/{p.stem}" for p in scripts), "```", ""]
        (target / f"{name}.md").write_text("\n".join(lines).rstrip() + "\n")
    (target / "report.md").write_text(
        "# The validation report\n\n"
        "As `python validation/make_report.py` last wrote it (validation/REPORT.md; the build does not rerun it).\n\n"
        "```{include} ../../validation/REPORT.md\n:relative-images:\n:heading-offset: 1\n```\n")
    toc = "\n".join([*folders, "report"])
    (target / "index.md").write_text(
        "# Validation\n\n"
        "```{include} ../../validation/README.md\n:start-after: <!-- layout -->\n:end-before: <!-- /layout -->\n```\n\n"
        f"```{{toctree}}\n:maxdepth: 1\n\n{toc}\n```\n")


def write_all(docs, root):
    validation_pages(docs, root)
    # docs/examples.md was the scenarios' page before the gallery (docs/examples/): a copy left in a checkout
    # would be a page outside every toctree, which -W fails
    (docs / "examples.md").unlink(missing_ok=True)

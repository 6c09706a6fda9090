"""The package's layers (README, "Architecture"): each module imports only
its own layer and the layers below, no solver imports another solver, and
the import graph has no circle. Imports inside functions count too."""
import ast
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1] / "exudyn_bearing"

#: Layer of each top-level part of the package, bottom first.
LAYERS = {"_jit": 0, "data": 1, "physics": 2, "model": 3, "solvers": 4, "outputs": 5, "simulate": 6, "sweep": 6,
          "datasets": 6, "cli": 7, "__init__": 8, "__main__": 8, "defaults": 8}


def module_name(path: Path) -> str:
    rel = path.relative_to(PACKAGE.parent).with_suffix("")
    parts = list(rel.parts)
    if parts[-1] == "__init__" and len(parts) > 1:
        parts = parts[:-1]
    return ".".join(parts)


def imports_of(path: Path) -> set[str]:
    """Modules of the package that ``path`` imports (absolute names)."""
    tree = ast.parse(path.read_text())
    own = module_name(path).split(".")
    package = own if path.name == "__init__.py" else own[:-1]
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom):
            if node.level:
                base = package[:len(package) - node.level + 1]
                target = ".".join(base + ([node.module] if node.module else []))
            else:
                target = node.module or ""
            if target.split(".")[0] != "exudyn_bearing":
                continue
            found.add(target)
            for alias in node.names:  # "from . import kernels" imports a module
                candidate = f"{target}.{alias.name}"
                if (PACKAGE.parent / Path(*candidate.split("."))).with_suffix(".py").exists() or \
                        (PACKAGE.parent / Path(*candidate.split("."))).is_dir():
                    found.add(candidate)
        elif isinstance(node, ast.Import):
            found.update(a.name for a in node.names if a.name.split(".")[0] == "exudyn_bearing")
    return found


MODULES = {module_name(p): p for p in sorted(PACKAGE.rglob("*.py"))}
GRAPH = {m: imports_of(p) for m, p in MODULES.items()}


def part(module: str) -> str:
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else "__init__"


def solver(module: str) -> str | None:
    parts = module.split(".")
    return parts[2] if len(parts) > 2 and parts[1] == "solvers" else None


@pytest.mark.parametrize("module", sorted(MODULES))
def test_imports_only_lower_layers(module):
    own = LAYERS[part(module)]
    for target in GRAPH[module]:
        if target == "exudyn_bearing":
            assert part(module) in ("__init__", "__main__", "cli"), f"{module} imports the package root"
            continue
        assert LAYERS[part(target)] <= own, f"{module} (layer {part(module)}) imports {target} (layer {part(target)})"


@pytest.mark.parametrize("module", sorted(m for m in MODULES if solver(m)))
def test_no_solver_imports_another_solver(module):
    for target in GRAPH[module]:
        other = solver(target)
        assert other is None or other == solver(module), f"{module} imports another solver: {target}"


def test_no_import_circle():
    # depth-first search for a back edge over the package's module graph
    def resolve(target):
        while target not in MODULES and "." in target:
            target = target.rsplit(".", 1)[0]
        return target if target in MODULES else None

    edges = {m: {t for t in map(resolve, GRAPH[m]) if t and t != m} for m in MODULES}
    # a package's __init__ importing its own submodules is the usual re-export, not a circle
    for m in edges:
        if MODULES[m].name == "__init__.py":
            edges[m] = {t for t in edges[m] if not t.startswith(m + ".")}
    state, stack = {}, []

    def visit(m):
        state[m] = "open"
        stack.append(m)
        for t in sorted(edges[m]):
            if state.get(t) == "open":
                raise AssertionError("import circle: " + " -> ".join(stack[stack.index(t):] + [t]))
            if t not in state:
                visit(t)
        stack.pop()
        state[m] = "done"

    for m in sorted(MODULES):
        if m not in state:
            visit(m)


def test_the_checker_sees_imports():
    # guards the test itself: known edges are found
    assert "exudyn_bearing.model.contact" in GRAPH["exudyn_bearing.solvers.reference.integrators"]
    assert "exudyn_bearing.data" in GRAPH["exudyn_bearing.physics.load_distribution"]
    assert any(t.startswith("exudyn_bearing.solvers.reference") for t in GRAPH["exudyn_bearing.simulate"])

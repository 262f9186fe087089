"""The workspace's package layout stays as docs/architecture.md draws it.

Every src/ package's Python (modules, launch files, scripts with a python shebang) is parsed
and each import of another workspace package becomes an edge between packages. The tests
fail on a cycle between packages, on an edge its package.xml does not declare, on turtlesim
(the simulator, a leaf upstream) importing any workspace package but node_runtime, and on
my_robot_controller's nodes importing more than interfaces and node_runtime, and on a package
importing another package's `verb` modules (a `ros2` command's verbs are its own: what other
code may use is the command's `api`) or another package's private (underscore-named) modules.
Launch files (`*.launch.py`) count for cycles and package.xml, not for the turtlesim and course
rules: a launch file is run by `ros2 launch`, it is no part of a node. A package's tests (its
`test/` folder) count for package.xml (a `<test_depend>` will do) and for cycles (colcon orders
packages by their test dependencies too), not for the drawing nor for those two rules.

`python tests/test_layout.py [--mermaid]` prints the dependency table (or the drawing) of
docs/architecture.md.
"""

from __future__ import annotations

import ast
import re
import sys
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
SRC = REPO / 'src'
DEPEND_TAGS = ('depend', 'build_depend', 'build_export_depend', 'exec_depend', 'test_depend',
               'buildtool_depend', 'run_depend')
IMPORT_FUNCTIONS = ('import_module', '__import__')  # importlib.import_module('pkg.mod') too
# Workspace modules a package's code (launch files aside) may import besides its own.
ALLOWED_IN_CODE = {
    'node_runtime': set(),  # the runtime library under every node
    'turtlesim': {'node_runtime'},  # the simulator: a leaf, as upstream
    # the course's nodes, as a learner's package: interfaces and the runtime library
    'my_robot_controller': {'node_runtime', 'turtlesim', 'example_interfaces'},
}
# A package's internals: importable, but by no other package (the simulator's code).
PRIVATE_MODULES = {'turtlesim_py': 'turtlesim', 'logging_demo_py': 'logging_demo',
                   'slam_toolbox_py': 'slam_toolbox'}


@dataclass
class Package:
    name: str
    path: Path
    declared: set[str]
    modules: set[str] = field(default_factory=set)  # top-level import names it provides
    # imported workspace package -> where (file:line), first occurrence of each
    imports: dict[str, str] = field(default_factory=dict)
    # workspace module -> where, imported by code that is no launch file
    code_imports: dict[str, str] = field(default_factory=dict)
    modules_imported: dict[str, str] = field(default_factory=dict)  # every workspace module
    # imported workspace package -> where, by the package's tests (its test/ folder) only
    test_imports: dict[str, str] = field(default_factory=dict)


def find_packages() -> dict[str, Package]:
    packages = {}
    for manifest in sorted(SRC.rglob('package.xml')):
        if any(part in ('build', 'install', 'log', 'templates') for part in
               manifest.relative_to(SRC).parts):
            continue
        root = ET.parse(manifest).getroot()
        name = root.findtext('name', '').strip()
        declared = {element.text.strip() for tag in DEPEND_TAGS for element in root.iter(tag)
                    if element.text}
        package = Package(name, manifest.parent, declared)
        # An interface package's generated module, or an ament_python package's own name.
        package.modules.add(name)
        package.modules.update(child.name for child in manifest.parent.iterdir()
                               if (child / '__init__.py').is_file())
        packages[name] = package
    return packages


def python_files(package: Package, packages: dict[str, Package]) -> list[Path]:
    """The package's Python files, not those of a package nested inside it."""
    nested = [other.path for other in packages.values()
              if other.path != package.path and package.path in other.path.parents]
    files = []
    for path in sorted(package.path.rglob('*')):
        if not path.is_file() or any(root == path or root in path.parents for root in nested):
            continue
        if path.suffix == '.py' or (not path.suffix and _has_python_shebang(path)):
            files.append(path)
    return files


def _has_python_shebang(path: Path) -> bool:
    try:
        with open(path, 'rb') as handle:
            first = handle.readline(200)
    except OSError:
        return False
    return first.startswith(b'#!') and b'python' in first


def imported_names(path: Path) -> list[tuple[str, int]]:
    """(top-level module name, line) of every absolute import, also inside functions."""
    tree = ast.parse(path.read_text(), filename=str(path))
    names = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names += [(alias.name.split('.')[0], node.lineno) for alias in node.names]
        elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            names.append((node.module.split('.')[0], node.lineno))
        elif (isinstance(node, ast.Call) and node.args
              and isinstance(node.args[0], ast.Constant) and isinstance(node.args[0].value, str)
              and getattr(node.func, 'attr', getattr(node.func, 'id', None))
              in IMPORT_FUNCTIONS):
            names.append((node.args[0].value.split('.')[0], node.lineno))
    return names


def imported_modules(path: Path) -> list[tuple[str, int]]:
    """(dotted module, line) of every absolute import, also inside functions: `import a.b` is
    a.b; `from a.b import c` is a.b and a.b.c (c may be a module); import_module('a.b') a.b."""
    tree = ast.parse(path.read_text(), filename=str(path))
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            found += [(alias.name, node.lineno) for alias in node.names]
        elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            found.append((node.module, node.lineno))
            found += [(f'{node.module}.{alias.name}', node.lineno) for alias in node.names
                      if alias.name != '*']
        elif (isinstance(node, ast.Call) and node.args
              and isinstance(node.args[0], ast.Constant) and isinstance(node.args[0].value, str)
              and getattr(node.func, 'attr', getattr(node.func, 'id', None))
              in IMPORT_FUNCTIONS):
            found.append((node.args[0].value, node.lineno))
    return found


def known_modules(packages: dict[str, Package]) -> set[str]:
    """Dotted names of every module and package of the workspace's Python (from the files)."""
    found = set()
    for package in packages.values():
        for path in python_files(package, packages):
            if path.suffix != '.py' or path.name.endswith('.launch.py'):
                continue
            parts = path.relative_to(package.path).with_suffix('').parts
            if parts and parts[0] in package.modules:
                found.add('.'.join(parts[:-1] if parts[-1] == '__init__' else parts))
    return found


def boundary_violations(importer: str, module: str, owner: dict[str, str],
                        modules: set[str]) -> list[str]:
    """Why `importer`'s import of `module` crosses another package's boundary ([] if not): a
    command's verb modules (`<pkg>.verb...`) and underscore-named modules (`modules` tells a
    module from a name imported from one) are their package's."""
    parts = module.split('.')
    target = owner.get(parts[0])
    if target is None or target == importer:
        return []
    found = []
    if len(parts) > 1 and parts[1] == 'verb':
        found.append(f"{target}'s verb module")
    while parts and '.'.join(parts) not in modules:
        parts = parts[:-1]  # `from a.b import c`: c may be a name, not a module
    private = [part for part in parts[1:] if part.startswith('_') and not part.startswith('__')]
    if private:
        found.append(f"{target}'s private module {'.'.join(parts[:parts.index(private[0]) + 1])}")
    return found


def scan_boundaries(packages: dict[str, Package]) -> list[str]:
    """Every import of one package that reaches into another's verbs or private modules."""
    owner = {module: package.name for package in packages.values()
             for module in package.modules}
    modules = known_modules(packages)
    found: dict[tuple[str, str], str] = {}  # (where, why) -> what; `from a import b` once
    for package in packages.values():
        for path in python_files(package, packages):
            for module, line in imported_modules(path):
                where = f'{path.relative_to(REPO)}:{line}'
                for why in boundary_violations(package.name, module, owner, modules):
                    found.setdefault((where, why), f'{package.name} imports {module} ({where})')
    return [f'{what}: {why}' for (_, why), what in found.items()]


def scan() -> dict[str, Package]:
    packages = find_packages()
    owner = {module: package.name for package in packages.values()
             for module in package.modules}
    for package in packages.values():
        for path in python_files(package, packages):
            for module, line in imported_names(path):
                target = owner.get(module)
                if target is None or target == package.name:
                    continue
                where = f'{path.relative_to(REPO)}:{line}'
                if package.path / 'test' in path.parents:
                    package.test_imports.setdefault(target, where)
                    package.modules_imported.setdefault(module, where)
                    continue
                package.imports.setdefault(target, where)
                package.modules_imported.setdefault(module, where)
                if not path.name.endswith('.launch.py'):
                    package.code_imports.setdefault(module, where)
    return packages


def cycles(packages: dict[str, Package], tests: bool = False) -> list[list[str]]:
    """Strongly connected components of more than one package (Tarjan); with `tests`, the
    tests' imports count as edges too."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found = []

    def visit(name: str) -> None:
        index[name] = low[name] = len(index)
        stack.append(name)
        on_stack.add(name)
        targets = set(packages[name].imports)
        if tests:
            targets |= set(packages[name].test_imports)
        for target in sorted(targets):
            if target not in index:
                visit(target)
                low[name] = min(low[name], low[target])
            elif target in on_stack:
                low[name] = min(low[name], index[target])
        if low[name] == index[name]:
            component = []
            while True:
                member = stack.pop()
                on_stack.discard(member)
                component.append(member)
                if member == name:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for name in sorted(packages):
        if name not in index:
            visit(name)
    return found


def table(packages: dict[str, Package]) -> str:
    lines = ['| package | imports (workspace packages) | not in package.xml |', '|---|---|---|']
    for name in sorted(packages):
        package = packages[name]
        imports = sorted(package.imports)
        undeclared = [target for target in imports if target not in package.declared]
        lines.append(f"| {name} | {', '.join(imports) or '-'} | {', '.join(undeclared) or '-'} |")
    return '\n'.join(lines)


def test_no_import_cycle_between_packages():
    found = cycles(scan(), tests=True)
    assert found == [], f'import cycles between packages: {found}\n{table(scan())}'


def test_every_cross_package_import_is_declared_in_package_xml():
    missing = [f'{package.name} imports {target} ({where}) without declaring it in '
               f'{package.path.relative_to(REPO)}/package.xml'
               for package in scan().values()
               for target, where in sorted({**package.test_imports, **package.imports}.items())
               if target not in package.declared]
    assert missing == [], '\n'.join(missing)


def test_turtlesim_and_the_course_nodes_import_only_what_they_may():
    packages = scan()
    for name, allowed in sorted(ALLOWED_IN_CODE.items()):
        extra = {module: where for module, where in packages[name].code_imports.items()
                 if module not in allowed}
        assert extra == {}, f'{name} may import only {sorted(allowed)} of the workspace'


def test_no_package_imports_another_packages_internals():
    # e.g. the runtime helpers once lived in turtlesim_py: they are node_runtime's now.
    found = [f'{package.name} imports {module} ({where}), internal to {PRIVATE_MODULES[module]}'
             for package in scan().values()
             for module, where in sorted(package.modules_imported.items())
             if PRIVATE_MODULES.get(module, package.name) != package.name]
    assert found == [], '\n'.join(found)


def test_no_package_imports_another_packages_verbs_or_private_modules():
    # A verb module is its command's: what other code may use is the command's `api`
    # (`ros2topic.api`, not `ros2topic.verb.echo`); an underscore-named module is its package's.
    found = scan_boundaries(find_packages())
    assert found == [], '\n'.join(found)


def test_the_boundary_check_catches_a_verb_import_a_private_import_and_an_undeclared_one(
        tmp_path):
    # The checker itself, on a scratch package that does all three wrong things.
    (tmp_path / 'scratch').mkdir()
    (tmp_path / 'scratch' / 'package.xml').write_text(
        '<package format="3"><name>scratch</name><exec_depend>ros2topic</exec_depend>'
        '</package>')
    (tmp_path / 'scratch' / 'scratch').mkdir()
    module = tmp_path / 'scratch' / 'scratch' / '__init__.py'
    module.write_text('from ros2topic.verb import echo\nimport rosbag2_py._session\n'
                      'from ros2cli.node import direct\n')
    packages = find_packages()
    scratch = Package('scratch', tmp_path / 'scratch', {'ros2topic'}, {'scratch'})
    owner = {name: package.name for package in packages.values() for name in package.modules}
    modules = known_modules(packages)
    why = [reason for name, _ in imported_modules(module)
           for reason in boundary_violations('scratch', name, owner, modules)]
    assert why == ["ros2topic's verb module", "ros2topic's verb module",
                   "rosbag2_py's private module rosbag2_py._session"]
    undeclared = {owner[name.split('.')[0]] for name, _ in imported_modules(module)
                  if name.split('.')[0] in owner} - scratch.declared
    assert undeclared == {'ros2cli', 'rosbag2_py'}
    # A package may import its own verbs and private modules; a private name of a public
    # module is a name, not a module.
    assert boundary_violations('ros2topic', 'ros2topic.verb.echo', owner, modules) == []
    assert boundary_violations('rosbag2_py', 'rosbag2_py._session', owner, modules) == []
    assert boundary_violations('ros2bag', 'rosbag2_py._session.exit_now', owner, modules) == [
        "rosbag2_py's private module rosbag2_py._session"]


# Ours on purpose: tutorial packages and the course's own; on apt Jazzy they overlay upstream's.
OVERLAY_ON_PURPOSE = {'turtlesim', 'example_interfaces', 'my_robot_controller', 'node_runtime',
                      'ws_testing',  # the tests' fixtures: colcon test on apt Jazzy uses them too
                      'turtle_tf2_py', 'urdf_tutorial', 'urdf_tutorial_r2d2',
                      # the MuJoCo simulator: no upstream package of these names
                      'mujoco_sim', 'mujoco_sim_interfaces', 'diffbot_description',
                      'diffbot_bringup'}


def test_every_package_is_either_a_stand_in_to_skip_on_apt_jazzy_or_ours():
    # The README's apt-Jazzy build skips tools/apt_jazzy_skip.txt: a new stand-in for an
    # upstream package that is missing there would shadow the real one.
    listed = [line.strip() for line in (REPO / 'tools' / 'apt_jazzy_skip.txt').read_text()
              .splitlines() if line.strip() and not line.startswith('#')]
    packages = set(find_packages())
    assert sorted(set(listed) - packages) == [], 'listed but not a package of src/'
    unclassified = packages - set(listed) - OVERLAY_ON_PURPOSE
    assert sorted(unclassified) == [], ('add to tools/apt_jazzy_skip.txt (stands in for an '
                                        'upstream package) or to OVERLAY_ON_PURPOSE')


def test_the_checker_sees_imports_inside_functions_and_scripts(tmp_path):
    # The checker itself: a lazy import in a function and a script without .py both count.
    packages = scan()
    assert 'turtlesim' in packages and 'rqt_web' in packages
    script = SRC / 'turtlesim' / 'scripts' / 'turtlesim_node'
    assert script in python_files(packages['turtlesim'], packages)
    probe = tmp_path / 'probe.py'
    probe.write_text('def f():\n    import os.path\n'
                     '    importlib.import_module("json.decoder")\n')
    assert [name for name, _ in imported_names(probe)] == ['os', 'json']


def test_the_architecture_drawing_has_exactly_the_imports_of_the_code():
    # Solid arrows in docs/architecture.md are imports (`A --> B`); dotted ones are entry-point
    # plugins, which no import shows.
    drawing = (REPO / 'docs' / 'architecture.md').read_text().split('```mermaid\n')[1]
    drawn = set(re.findall(r'^ *(\w+) --> (\w+)$', drawing.split('```')[0], re.MULTILINE))
    imported = {(name, target) for name, package in scan().items() for target in package.imports}
    assert (sorted(imported - drawn), sorted(drawn - imported)) == ([], []), (
        '(not drawn, drawn but not imported): redraw with python tests/test_layout.py --mermaid')


def mermaid(packages: dict[str, Package]) -> str:
    """`A --> B`: A imports B (packages that import and are imported by nothing left out)."""
    lines = ['graph LR']
    for name in sorted(packages):
        lines += [f'    {name} --> {target}' for target in sorted(packages[name].imports)]
    return '\n'.join(lines)


if __name__ == '__main__':
    found = scan()
    if '--mermaid' in sys.argv:
        print(mermaid(found))
    else:
        print(table(found))
        print(f'\nimport cycles between packages: {cycles(found) or 0}')
    sys.exit(0)

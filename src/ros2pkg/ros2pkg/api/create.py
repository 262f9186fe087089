"""`ros2 pkg create`: write a new package's files the way Jazzy's ros2pkg lays them out.

Templates live in `templates/<kind>/*.in`; `@name@` marks a value. Sections that depend on the
options (dependencies, the node) are built here, so the templates stay plain text.
"""

from __future__ import annotations

import getpass
import os
import re
import shutil
import subprocess
from dataclasses import dataclass, field
from typing import TextIO

from ros2cli.verb_context import CliError

BUILD_TYPES = ('cmake', 'ament_cmake', 'ament_python')
DEFAULT_DESCRIPTION = 'TODO: Package description'
DEFAULT_LICENSE = 'TODO: License declaration'
_TEMPLATES = os.path.join(os.path.dirname(os.path.dirname(__file__)), 'templates')
# REP 144: a lowercase letter first, then lowercase letters, digits and single underscores.
_PACKAGE_NAME = re.compile(r'^[a-z](?:[a-z0-9]|_(?=[a-z0-9]))*$')
_IDENTIFIER = re.compile(r'^[A-Za-z_][A-Za-z0-9_]*$')
# Dependency keys may be packages or rosdep keys (`python3-pytest`).
_DEPENDENCY = re.compile(r'^[A-Za-z0-9][A-Za-z0-9_.+-]*$')


@dataclass
class PackageSpec:
    """What the user asked for, checked by `validate`."""

    name: str
    build_type: str = 'ament_cmake'
    package_format: int = 3
    description: str = DEFAULT_DESCRIPTION
    license: str = DEFAULT_LICENSE
    maintainer_name: str = field(default_factory=getpass.getuser)
    maintainer_email: str | None = None
    dependencies: list[str] = field(default_factory=list)
    node_name: str | None = None
    library_name: str | None = None
    destination: str = os.curdir

    @property
    def buildtool_dependencies(self) -> list[str]:
        if self.build_type != 'ament_cmake':
            return []
        # A C++ library's CMakeLists uses ament_cmake_ros (shared or static, as upstream).
        return ['ament_cmake_ros'] if self.library_name else ['ament_cmake']

    @property
    def test_dependencies(self) -> list[str]:
        if self.build_type == 'ament_cmake':
            return ['ament_lint_auto', 'ament_lint_common']
        if self.build_type == 'ament_python':
            return ['ament_copyright', 'ament_flake8', 'ament_pep257', 'python3-pytest']
        return []

    @property
    def maintainer(self) -> str:
        return f'{self.maintainer_name} <{self.maintainer_email}>'


def default_email(name: str) -> str:
    """The global git user.email, else `<name>@todo.todo`, as ros2pkg does."""
    git = shutil.which('git')
    if git:
        try:
            email = subprocess.run([git, 'config', 'user.email'], capture_output=True,
                                   text=True, timeout=5).stdout.strip()
        except (OSError, subprocess.SubprocessError):
            email = ''
        if email:
            return email
    return f'{name}@todo.todo'


def validate(spec: PackageSpec) -> None:
    """Refuse what would give a package colcon or catkin_pkg cannot handle (CliError)."""
    if not _PACKAGE_NAME.match(spec.name):
        raise CliError(f"Invalid package name '{spec.name}': it must start with a lowercase "
                       'letter and contain only lowercase letters, digits and single '
                       'underscores, not ending in one (REP 144)')
    if spec.build_type == 'ament_python' and spec.name == 'test':
        raise CliError("Aborted since 'ament_python' packages can't be named 'test'. Please "
                       'choose a different package name.')
    for option, value in (('--node-name', spec.node_name),
                          ('--library-name', spec.library_name)):
        if value is not None and not _IDENTIFIER.match(value):
            raise CliError(f"Invalid {option} '{value}': it must be a C/Python identifier "
                           '(letters, digits and underscores, not starting with a digit)')
    if spec.library_name and spec.build_type == 'cmake':
        raise CliError('Invalid --library-name: with --build-type cmake no library template '
                       'is provided here; use ament_cmake or ament_python')
    for dependency in spec.dependencies:
        if not _DEPENDENCY.match(dependency):
            raise CliError(f"Invalid dependency '{dependency}': allowed are letters, digits "
                           "and '_', '-', '.', '+'")
    for option, value in (('--description', spec.description), ('--license', spec.license),
                          ('--maintainer-name', spec.maintainer_name)):
        if not value.strip() or any(c in value for c in '<>&\n'):
            raise CliError(f"Invalid {option} '{value}': it must be non-empty text without "
                           "'<', '>', '&' or line breaks")
    from catkin_pkg.package import InvalidPackage, Package, Person
    try:
        Package(package_format=spec.package_format, name=spec.name, version='0.0.0',
                description=spec.description, licenses=[spec.license],
                maintainers=[Person(spec.maintainer_name, spec.maintainer_email)],
                ).validate()
    except InvalidPackage as error:
        detail = ' '.join(str(error).split())
        if 'email' in detail.lower():
            raise CliError(f"Invalid --maintainer-email '{spec.maintainer_email}': {detail}"
                           ) from None
        raise CliError(f'Invalid package: {detail}') from None


def print_summary(spec: PackageSpec, out: TextIO) -> None:
    print('going to create a new package', file=out)
    print('package name:', spec.name, file=out)
    print('destination directory:', os.path.abspath(spec.destination), file=out)
    print('package format:', spec.package_format, file=out)
    print('version:', '0.0.0', file=out)
    print('description:', spec.description, file=out)
    print('maintainer:', [spec.maintainer], file=out)
    print('licenses:', [spec.license], file=out)
    print('build type:', spec.build_type, file=out)
    print('dependencies:', list(spec.dependencies), file=out)
    if spec.node_name:
        print('node_name:', spec.node_name, file=out)
    if spec.library_name:
        print('library_name:', spec.library_name, file=out)


class _Writer:
    """Creates folders and files, printing each as ros2pkg does."""

    def __init__(self, spec: PackageSpec, out: TextIO) -> None:
        self.out = out
        self.values = {
            'package_name': spec.name, 'package_format': str(spec.package_format),
            'description': spec.description, 'license': spec.license,
            'maintainer_name': spec.maintainer_name,
            'maintainer_email': spec.maintainer_email or '',
            'build_type': spec.build_type,
        }

    def folder(self, base: str, name: str) -> str:
        path = os.path.join(base, name)
        print('creating folder', path, file=self.out)
        os.makedirs(path, exist_ok=True)
        return path

    def file(self, template: str, directory: str, name: str, **extra: str) -> str:
        with open(os.path.join(_TEMPLATES, template), encoding='utf-8') as source:
            text = source.read()
        values = {**self.values, **extra}
        text = re.sub(r'@([a-z_]+)@', lambda m: values.get(m.group(1), m.group(0)), text)
        return self.text(text, directory, name)

    def text(self, text: str, directory: str, name: str) -> str:
        path = os.path.join(directory, name)
        print('creating', path, file=self.out)
        with open(path, 'w', encoding='utf-8') as target:
            target.write(text)
        return path


def _depend_blocks(spec: PackageSpec) -> str:
    blocks = ''
    for tag, names in (('buildtool_depend', spec.buildtool_dependencies),
                       ('depend', spec.dependencies),
                       ('test_depend', spec.test_dependencies)):
        if names:
            blocks += ''.join(f'  <{tag}>{name}</{tag}>\n' for name in names) + '\n'
    return blocks


def _find_dependencies(spec: PackageSpec) -> str:
    if spec.dependencies:
        found = ''.join(f'find_package({dep} REQUIRED)\n' for dep in spec.dependencies)
        return found if spec.build_type == 'ament_cmake' else '\n# find dependencies\n' + found
    return ('# uncomment the following section in order to fill in\n'
            '# further dependencies manually.\n'
            '# find_package(<dependency> REQUIRED)\n')


def _target_dependencies(target: str, spec: PackageSpec) -> str:
    if not spec.dependencies:
        return ''
    return (f'ament_target_dependencies(\n  {target}\n'
            + ''.join(f'  "{dep}"\n' for dep in spec.dependencies) + ')\n')


def _ament_cmake_library(spec: PackageSpec) -> dict[str, str]:
    """The CMakeLists parts of a C++ library (--library-name): found, built, exported."""
    library, name = spec.library_name, spec.name
    if not library:
        return {'library_find': '', 'library_block': '', 'library_exports': ''}
    block = (f'\nadd_library({library} src/{library}.cpp)\n'
             f'add_library({name}::{library} ALIAS {library})\n'
             f'target_compile_features({library} PUBLIC c_std_99 cxx_std_17)'
             '  # Require C99 and C++17\n'
             f'target_include_directories({library} PUBLIC\n'
             '  $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>\n'
             '  $<INSTALL_INTERFACE:include/${PROJECT_NAME}>)\n'
             + _target_dependencies(library, spec)
             + '\n# The visibility macros export (not import) while the library is built.\n'
             f'target_compile_definitions({library} PRIVATE "{name.upper()}_BUILDING_LIBRARY")\n'
             '\ninstall(\n  DIRECTORY include/\n  DESTINATION include/${PROJECT_NAME}\n)\n'
             f'install(\n  TARGETS {library}\n  EXPORT export_${{PROJECT_NAME}}\n'
             '  ARCHIVE DESTINATION lib\n  LIBRARY DESTINATION lib\n  RUNTIME DESTINATION bin\n)\n')
    exports = ('\nament_export_include_directories(\n  "include/${PROJECT_NAME}"\n)\n'
               f'ament_export_libraries(\n  {library}\n)\n'
               'ament_export_targets(\n  export_${PROJECT_NAME}\n)\n')
    return {'library_find': 'find_package(ament_cmake_ros REQUIRED)\n',
            'library_block': block, 'library_exports': exports}


def _ament_cmake_node(spec: PackageSpec) -> str:
    node = spec.node_name
    if not node:
        return ''
    block = (f'\nadd_executable({node} src/{node}.cpp)\n'
             f'target_include_directories({node} PUBLIC\n'
             '  $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>\n'
             '  $<INSTALL_INTERFACE:include/${PROJECT_NAME}>)\n')
    if spec.library_name:  # the library brings the compile features and dependencies
        return block + (f'target_link_libraries({node} {spec.library_name})\n'
                        f'\ninstall(TARGETS {node}\n  DESTINATION lib/${{PROJECT_NAME}})\n')
    block += (f'target_compile_features({node} PUBLIC c_std_99 cxx_std_17)'
              '  # Require C99 and C++17\n')
    block += _target_dependencies(node, spec)
    return block + f'\ninstall(TARGETS {node}\n  DESTINATION lib/${{PROJECT_NAME}})\n'


def _cmake_node(spec: PackageSpec) -> str:
    node, name = spec.node_name, spec.name
    if not node:
        return ''
    block = f'\nadd_executable({node} src/{node}.cpp)\n'
    if spec.dependencies:
        block += (f'target_include_directories({node} PUBLIC\n'
                  '  $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>\n'
                  '  $<INSTALL_INTERFACE:include>\n'
                  + ''.join(f'  PUBLIC ${{{dep}_INCLUDE_DIRS}}\n' for dep in spec.dependencies)
                  + ')\n')
    block += (f'target_compile_features({node} PUBLIC c_std_99 cxx_std_17)'
              '  # Require C99 and C++17\n')
    if spec.dependencies:
        block += (f'target_link_libraries({node}\n'
                  + ''.join(f' ${{{dep}_LIBRARIES}}\n' for dep in spec.dependencies) + ')\n')
    return block + (
        f'\ninstall(\n  TARGETS {node}\n  EXPORT export_{name}\n'
        '  DESTINATION lib/${PROJECT_NAME})\n'
        '\n# export targets\n'
        f'set(export_targets ${{export_targets}};{node})\n'
        f'export(EXPORT export_{name}\n'
        f'  FILE "${{PROJECT_BINARY_DIR}}/export_{name}.cmake")\n'
        f'\n# Create the {name}Config.cmake\n'
        'set(CONF_INCLUDE_DIRS "${CMAKE_INSTALL_PREFIX}/include")\n'
        f'configure_file({name}Config.cmake.in\n'
        f'  "${{PROJECT_BINARY_DIR}}/${{CMAKE_FILES_DIRECTORY}}/{name}Config.cmake" @ONLY)\n'
        f'\n# Create the {name}ConfigVersion.cmake\n'
        f'configure_file({name}ConfigVersion.cmake.in\n'
        f'  "${{PROJECT_BINARY_DIR}}/{name}ConfigVersion.cmake" @ONLY)\n'
        '\ninstall(FILES\n'
        f'  "${{PROJECT_BINARY_DIR}}/${{CMAKE_FILES_DIRECTORY}}/{name}Config.cmake"\n'
        f'  "${{PROJECT_BINARY_DIR}}/{name}ConfigVersion.cmake"\n'
        '  DESTINATION "share/${PROJECT_NAME}/cmake" COMPONENT dev)\n'
        f'install(EXPORT export_{name}\n'
        '  DESTINATION "share/${PROJECT_NAME}/cmake"\n'
        f'  FILE export_{name}.cmake\n'
        '  COMPONENT dev)\n')


def create(spec: PackageSpec, license_files: list[str] | None, out: TextIO) -> None:
    """Write the package (the caller has validated `spec` and printed the summary)."""
    write = _Writer(spec, out)
    package_dir = write.folder(spec.destination, spec.name)
    write.file('common/package.xml.in', package_dir, 'package.xml',
               depend_blocks=_depend_blocks(spec))
    source_dir = None
    if spec.build_type in ('cmake', 'ament_cmake'):
        print('creating source and include folder', file=out)
        source_dir = write.folder(package_dir, 'src')
        write.folder(os.path.join(package_dir, 'include'), spec.name)
    else:
        print('creating source folder', file=out)
        source_dir = write.folder(package_dir, spec.name)

    if spec.build_type == 'ament_python':
        console = (f"            '{spec.node_name} = {spec.name}.{spec.node_name}:main'\n"
                   if spec.node_name else '')
        write.file('ament_python/setup.py.in', package_dir, 'setup.py', console_scripts=console)
        write.file('ament_python/setup.cfg.in', package_dir, 'setup.cfg')
        resource_dir = write.folder(package_dir, 'resource')
        write.text('', resource_dir, spec.name)
        write.text('', source_dir, '__init__.py')
        test_dir = write.folder(package_dir, 'test')
        for name in ('test_copyright.py', 'test_flake8.py', 'test_pep257.py'):
            write.file(f'ament_python/{name}.in', test_dir, name)
        if spec.node_name:
            write.file('ament_python/node.py.in', source_dir, spec.node_name + '.py')
        if spec.library_name:
            library_dir = write.folder(source_dir, spec.library_name)
            write.text('', library_dir, '__init__.py')
    elif spec.build_type == 'ament_cmake':
        write.file('ament_cmake/CMakeLists.txt.in', package_dir, 'CMakeLists.txt',
                   find_dependencies=_find_dependencies(spec),
                   node_block=_ament_cmake_node(spec), **_ament_cmake_library(spec))
    else:
        write.file('cmake/CMakeLists.txt.in', package_dir, 'CMakeLists.txt',
                   find_dependencies=_find_dependencies(spec), node_block=_cmake_node(spec))
        executable = (f'set({spec.name}_EXECUTABLE {spec.node_name})\n'
                      if spec.node_name else '')
        write.file('cmake/Config.cmake.in.in', package_dir, f'{spec.name}Config.cmake.in',
                   executable_line=executable)
        write.file('cmake/ConfigVersion.cmake.in.in', package_dir,
                   f'{spec.name}ConfigVersion.cmake.in')
    if spec.build_type != 'ament_python' and spec.node_name:
        write.file('common/main.cpp.in', source_dir, spec.node_name + '.cpp')
    if spec.build_type == 'ament_cmake' and spec.library_name:
        _write_cpp_library(write, spec, source_dir, os.path.join(package_dir, 'include',
                                                                 spec.name))

    if license_files is not None:
        with open(os.path.join(package_dir, 'LICENSE'), 'w', encoding='utf-8') as target:
            target.write(''.join(license_files))


def _write_cpp_library(write: _Writer, spec: PackageSpec, source_dir: str,
                       include_dir: str) -> None:
    """An empty C++ class `<Library_Name>` in the package's namespace, as upstream's."""
    library = spec.library_name or ''
    values = {'library_name': library,
              'class_name': library.replace('_', ' ').title().replace(' ', ''),
              'guard': f'{spec.name.upper()}__{library.upper()}_HPP_'}
    write.file('cpp/library.hpp.in', include_dir, library + '.hpp', **values)
    write.file('cpp/library.cpp.in', source_dir, library + '.cpp', **values)
    write.file('cpp/visibility_control.h.in', include_dir, 'visibility_control.h',
               package_upper=spec.name.upper())

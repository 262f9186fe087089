"""`ros2 pkg`: create (Jazzy's output and files, bad input), executables, list, prefix, xml."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from ws_testing import ros2

MAINTAINER = ['--maintainer-name', 'user', '--maintainer-email', 'user@example.com']


def create(env: dict[str, str], cwd: Path, *args: str):
    import subprocess
    return subprocess.run(['ros2', 'pkg', 'create', *args], env=env, cwd=cwd,
                          capture_output=True, text=True, timeout=30,
                          stdin=subprocess.DEVNULL)


def summary(cwd: Path, name: str, build_type: str, node: str | None = None,
            dependencies: str = '[]', license_name: str = 'Apache-2.0') -> str:
    lines = ['going to create a new package', f'package name: {name}',
             f'destination directory: {cwd}', 'package format: 3', 'version: 0.0.0',
             'description: TODO: Package description',
             "maintainer: ['user <user@example.com>']", f"licenses: ['{license_name}']",
             f'build type: {build_type}', f'dependencies: {dependencies}']
    if node:
        lines.append(f'node_name: {node}')
    return '\n'.join(lines) + '\n'


def test_create_ament_python_prints_and_writes_what_jazzy_does(ros_env, tmp_path):
    result = create(ros_env, tmp_path, '--build-type', 'ament_python', '--license',
                    'Apache-2.0', '--node-name', 'my_node', 'my_package', *MAINTAINER)
    assert result.returncode == 0, result.stderr
    assert result.stderr == ''
    assert result.stdout == summary(tmp_path, 'my_package', 'ament_python', 'my_node') + (
        'creating folder ./my_package\n'
        'creating ./my_package/package.xml\n'
        'creating source folder\n'
        'creating folder ./my_package/my_package\n'
        'creating ./my_package/setup.py\n'
        'creating ./my_package/setup.cfg\n'
        'creating folder ./my_package/resource\n'
        'creating ./my_package/resource/my_package\n'
        'creating ./my_package/my_package/__init__.py\n'
        'creating folder ./my_package/test\n'
        'creating ./my_package/test/test_copyright.py\n'
        'creating ./my_package/test/test_flake8.py\n'
        'creating ./my_package/test/test_pep257.py\n'
        'creating ./my_package/my_package/my_node.py\n')
    package = tmp_path / 'my_package'
    assert sorted(str(p.relative_to(package)) for p in package.rglob('*') if p.is_file()) == [
        'LICENSE', 'my_package/__init__.py', 'my_package/my_node.py', 'package.xml',
        'resource/my_package', 'setup.cfg', 'setup.py', 'test/test_copyright.py',
        'test/test_flake8.py', 'test/test_pep257.py']
    assert (package / 'package.xml').read_text() == (
        '<?xml version="1.0"?>\n'
        '<?xml-model href="http://download.ros.org/schema/package_format3.xsd" '
        'schematypens="http://www.w3.org/2001/XMLSchema"?>\n'
        '<package format="3">\n'
        '  <name>my_package</name>\n'
        '  <version>0.0.0</version>\n'
        '  <description>TODO: Package description</description>\n'
        '  <maintainer email="user@example.com">user</maintainer>\n'
        '  <license>Apache-2.0</license>\n'
        '\n'
        '  <test_depend>ament_copyright</test_depend>\n'
        '  <test_depend>ament_flake8</test_depend>\n'
        '  <test_depend>ament_pep257</test_depend>\n'
        '  <test_depend>python3-pytest</test_depend>\n'
        '\n'
        '  <export>\n'
        '    <build_type>ament_python</build_type>\n'
        '  </export>\n'
        '</package>\n')
    setup_py = (package / 'setup.py').read_text()
    assert "            'my_node = my_package.my_node:main'\n        ],\n" in setup_py
    assert (package / 'setup.cfg').read_text() == (
        '[develop]\nscript_dir=$base/lib/my_package\n'
        '[install]\ninstall_scripts=$base/lib/my_package\n')
    assert (package / 'my_package/my_node.py').read_text() == (
        "def main():\n    print('Hi from my_package.')\n\n\n"
        "if __name__ == '__main__':\n    main()\n")
    assert "@pytest.mark.skip(reason='No copyright header has been placed in the generated " \
        "source file.')" in (package / 'test/test_copyright.py').read_text()
    assert 'Apache License\n                           Version 2.0, January 2004' in \
        (package / 'LICENSE').read_text()


def test_create_ament_cmake_with_dependencies(ros_env, tmp_path):
    result = create(ros_env, tmp_path, '--build-type', 'ament_cmake', '--license',
                    'Apache-2.0', '--node-name', 'my_node', 'my_package', *MAINTAINER,
                    '--dependencies', 'rclcpp', 'std_msgs')
    assert result.returncode == 0, result.stderr
    assert result.stdout == summary(tmp_path, 'my_package', 'ament_cmake', 'my_node',
                                    "['rclcpp', 'std_msgs']") + (
        'creating folder ./my_package\n'
        'creating ./my_package/package.xml\n'
        'creating source and include folder\n'
        'creating folder ./my_package/src\n'
        'creating folder ./my_package/include/my_package\n'
        'creating ./my_package/CMakeLists.txt\n'
        'creating ./my_package/src/my_node.cpp\n')
    package = tmp_path / 'my_package'
    xml = (package / 'package.xml').read_text()
    assert ('  <buildtool_depend>ament_cmake</buildtool_depend>\n\n'
            '  <depend>rclcpp</depend>\n  <depend>std_msgs</depend>\n\n'
            '  <test_depend>ament_lint_auto</test_depend>\n'
            '  <test_depend>ament_lint_common</test_depend>\n\n  <export>') in xml
    cmake = (package / 'CMakeLists.txt').read_text()
    assert ('find_package(ament_cmake REQUIRED)\nfind_package(rclcpp REQUIRED)\n'
            'find_package(std_msgs REQUIRED)\n\nadd_executable(my_node src/my_node.cpp)\n'
            ) in cmake
    assert ('ament_target_dependencies(\n  my_node\n  "rclcpp"\n  "std_msgs"\n)\n\n'
            'install(TARGETS my_node\n  DESTINATION lib/${PROJECT_NAME})\n\n'
            'if(BUILD_TESTING)\n  find_package(ament_lint_auto REQUIRED)\n') in cmake
    assert cmake.endswith('  ament_lint_auto_find_test_dependencies()\nendif()\n\n'
                          'ament_package()\n')
    assert 'printf("hello world my_package package\\n");' in \
        (package / 'src/my_node.cpp').read_text()


def test_create_unknown_license_warns_and_lists_the_known_ones(ros_env, tmp_path):
    result = create(ros_env, tmp_path, '--build-type', 'cmake', 'plain', *MAINTAINER)
    assert result.returncode == 0, result.stderr
    assert result.stdout.endswith(
        "creating ./plain/plainConfigVersion.cmake.in\n\n[WARNING]: Unknown license 'TODO: "
        "License declaration'.  This has been set in the package.xml, but no LICENSE file "
        'has been created.\nIt is recommended to use one of the ament license identifiers:\n'
        'Apache-2.0\nBSL-1.0\nBSD-2.0\nBSD-3-Clause\nBSD-2-Clause\nMIT\nMIT-0\nGPL-3.0-only\n'
        'LGPL-3.0-only\n')
    assert not (tmp_path / 'plain' / 'LICENSE').exists()
    listing = create(ros_env, tmp_path, '--license', '?', 'anything')
    assert listing.stdout.startswith('Supported licenses:\nApache-2.0\nBSL-1.0\n')


@pytest.mark.parametrize('name, extra, field', [
    ('My_package', [], "Invalid package name 'My_package'"),
    ('1robot', [], "Invalid package name '1robot'"),
    ('my-package', [], "Invalid package name 'my-package'"),
    ('my__package', [], "Invalid package name 'my__package'"),
    ('my_package_', [], "Invalid package name 'my_package_'"),
    ('test', ['--build-type', 'ament_python'], "Aborted since 'ament_python' packages can't"),
    ('good', ['--node-name', 'my-node'], "Invalid --node-name 'my-node'"),
    ('good', ['--maintainer-email', 'a@b.c'], "Invalid --maintainer-email 'a@b.c'"),
])
def test_create_refuses_bad_input_in_one_line(ros_env, tmp_path, name, extra, field):
    result = create(ros_env, tmp_path, name, *extra)
    assert result.returncode == 1
    assert result.stdout == ''
    assert result.stderr.startswith(field)
    assert result.stderr.count('\n') == 1, result.stderr
    assert list(tmp_path.iterdir()) == []


def test_create_refuses_an_existing_directory(ros_env, tmp_path):
    (tmp_path / 'taken').mkdir()
    result = create(ros_env, tmp_path, 'taken')
    assert result.returncode == 1
    assert result.stderr == ('Aborted! The directory already exists: ./taken (remove it, or '
                             'choose a different destination directory or package name)\n')


def test_ament_copyright_checks_headers(ros_env, tmp_path):
    header = (Path(__file__).resolve().parent.parent / 'ros2pkg/templates/'
              'ament_python/test_flake8.py.in').read_text().split('\n\n')[0]
    (tmp_path / 'good.py').write_text(header + '\n\nx = 1\n')
    (tmp_path / 'unknown.py').write_text('# Copyright 2026 Me\n# All rights reserved\nx = 1\n')
    (tmp_path / 'none.py').write_text('x = 1\n')
    (tmp_path / 'empty.py').write_text('')
    import subprocess
    result = subprocess.run(['ament_copyright', '--xunit-file', str(tmp_path / 'c.xunit.xml')],
                            cwd=tmp_path, env=ros_env, capture_output=True, text=True,
                            timeout=30)
    assert result.returncode == 1
    assert result.stderr == ('none.py: could not find copyright notice\n'
                             'unknown.py: copyright=2026 Me, license=<unknown>\n'
                             '2 errors, checked 4 files\n')
    assert 'failures="2"' in (tmp_path / 'c.xunit.xml').read_text()
    (tmp_path / 'none.py').unlink()
    (tmp_path / 'unknown.py').unlink()
    ok = subprocess.run(['ament_copyright'], cwd=tmp_path, env=ros_env, capture_output=True,
                        text=True, timeout=30)
    assert (ok.returncode, ok.stdout) == (0, 'No problems found, checked 2 files\n')


def test_executables_list_prefix_xml(ros_env):
    from ament_index_python.packages import get_package_prefix
    prefix = get_package_prefix('turtlesim')
    result = ros2(ros_env, 'pkg', 'executables', 'turtlesim')
    assert result.returncode == 0, result.stderr
    assert 'turtlesim turtlesim_node\n' in result.stdout
    assert result.stdout.splitlines() == sorted(result.stdout.splitlines())
    full = ros2(ros_env, 'pkg', 'executables', 'turtlesim', '--full-path')
    assert f'{prefix}/lib/turtlesim/turtlesim_node\n' in full.stdout
    assert ros2(ros_env, 'pkg', 'prefix', 'turtlesim').stdout == prefix + '\n'
    assert ros2(ros_env, 'pkg', 'prefix', '--share', 'turtlesim').stdout == \
        os.path.join(prefix, 'share', 'turtlesim') + '\n'
    listing = ros2(ros_env, 'pkg', 'list').stdout.splitlines()
    assert {'turtlesim', 'rclpy', 'sensor_msgs', 'ament_lint_auto'} <= set(listing)
    assert listing == sorted(listing)
    assert ros2(ros_env, 'pkg', 'xml', 'turtlesim', '-t', 'name').stdout == 'turtlesim\n'
    xml = ros2(ros_env, 'pkg', 'xml', 'turtlesim').stdout
    assert xml.startswith('<package format="3">\n  <name>turtlesim</name>')


@pytest.mark.parametrize('args, message', [
    (['prefix', 'no_such_pkg'], 'Package not found'),
    (['xml', 'no_such_pkg'], 'Package not found'),
    (['xml', 'turtlesim', '-t', 'no_such_tag'], 'XML tag not found'),
    (['executables', 'no_such_pkg'], "Package 'no_such_pkg' not found"),
])
def test_pkg_verbs_report_what_is_missing(ros_env, args, message):
    result = ros2(ros_env, 'pkg', *args)
    assert (result.returncode, result.stdout, result.stderr) == (1, '', message + '\n')


def test_interface_show_sensor_msgs_image(ros_env):
    result = ros2(ros_env, 'interface', 'show', 'sensor_msgs/msg/Image')
    assert result.returncode == 0, result.stderr
    for line in ('std_msgs/Header header', 'uint32 height', 'uint32 width', 'string encoding',
                 'uint8 is_bigendian', 'uint32 step', 'uint8[] data'):
        assert any(row.startswith(line) for row in result.stdout.splitlines()), line


def test_create_ament_cmake_with_a_library(ros_env, tmp_path):
    # --library-name: an empty C++ class with its visibility header, built and exported by
    # the CMakeLists (ament_cmake_ros), the node linked against it, as upstream's.
    result = create(ros_env, tmp_path, '--build-type', 'ament_cmake', '--license', 'MIT',
                    '--node-name', 'my_node', '--library-name', 'my_lib', 'cpp_pkg',
                    *MAINTAINER)
    assert (result.returncode, result.stderr) == (0, '')
    assert result.stdout == summary(tmp_path, 'cpp_pkg', 'ament_cmake', 'my_node',
                                    license_name='MIT') + (
        'library_name: my_lib\n'
        'creating folder ./cpp_pkg\n'
        'creating ./cpp_pkg/package.xml\n'
        'creating source and include folder\n'
        'creating folder ./cpp_pkg/src\n'
        'creating folder ./cpp_pkg/include/cpp_pkg\n'
        'creating ./cpp_pkg/CMakeLists.txt\n'
        'creating ./cpp_pkg/src/my_node.cpp\n'
        'creating ./cpp_pkg/include/cpp_pkg/my_lib.hpp\n'
        'creating ./cpp_pkg/src/my_lib.cpp\n'
        'creating ./cpp_pkg/include/cpp_pkg/visibility_control.h\n')
    package = tmp_path / 'cpp_pkg'
    assert '  <buildtool_depend>ament_cmake_ros</buildtool_depend>\n' in \
        (package / 'package.xml').read_text()
    cmake = (package / 'CMakeLists.txt').read_text()
    assert 'find_package(ament_cmake_ros REQUIRED)\n' in cmake
    assert 'add_library(my_lib src/my_lib.cpp)\nadd_library(cpp_pkg::my_lib ALIAS my_lib)\n' \
        in cmake
    assert 'target_link_libraries(my_node my_lib)\n' in cmake
    assert cmake.endswith('ament_export_libraries(\n  my_lib\n)\nament_export_targets(\n'
                          '  export_${PROJECT_NAME}\n)\n\nament_package()\n')
    header = (package / 'include/cpp_pkg/my_lib.hpp').read_text()
    assert header.startswith('#ifndef CPP_PKG__MY_LIB_HPP_\n#define CPP_PKG__MY_LIB_HPP_\n')
    assert 'class MyLib\n{\npublic:\n  MyLib();\n\n  virtual ~MyLib();\n};\n' in header
    assert 'MyLib::MyLib()\n{\n}\n' in (package / 'src/my_lib.cpp').read_text()
    refused = create(ros_env, tmp_path, '--build-type', 'cmake', '--library-name', 'lib', 'c')
    assert (refused.returncode, refused.stderr.count('\n')) == (1, 1)
    assert refused.stderr.startswith('Invalid --library-name: ')

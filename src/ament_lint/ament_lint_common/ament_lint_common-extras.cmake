# cppcheck and uncrustify are programs the pip install does not bring (apt packages). Where
# one is missing, its wheel's lint hook would fail with "Could not find ...": exclude that
# hook and add a test reporting the linter as skipped, with the reason, instead.
if(POLICY CMP0109)
  cmake_policy(SET CMP0109 NEW)  # a program must be executable to count as found
endif()
set(_ament_lint_common_missing "")
foreach(_ament_lint_common_tool cppcheck uncrustify)
  find_program(_ament_lint_common_${_ament_lint_common_tool}_bin
    NAMES ${_ament_lint_common_tool})
  if(NOT _ament_lint_common_${_ament_lint_common_tool}_bin)
    list(APPEND AMENT_LINT_AUTO_EXCLUDE ament_cmake_${_ament_lint_common_tool})
    list(APPEND _ament_lint_common_missing ${_ament_lint_common_tool})
  endif()
endforeach()
if(_ament_lint_common_missing)
  ament_register_extension("ament_lint_auto" "ament_lint_common"
    "ament_lint_common_missing_tools_hook.cmake")
endif()

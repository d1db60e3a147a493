# Run at every build (cmake -P): writes OUT, a Fortran module with the git
# commit the build was made from ('-dirty' when tracked files differ from it;
# 'unknown' outside a git checkout). The file is rewritten only when the text
# changes, so an unchanged commit recompiles nothing.
set(commit unknown)
find_package(Git QUIET)
if(GIT_FOUND)
  execute_process(COMMAND ${GIT_EXECUTABLE} rev-parse HEAD WORKING_DIRECTORY ${SOURCE_DIR}
                  OUTPUT_VARIABLE head RESULT_VARIABLE failed OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(NOT failed AND head)
    set(commit ${head})
    execute_process(COMMAND ${GIT_EXECUTABLE} status --porcelain --untracked-files=no
                    WORKING_DIRECTORY ${SOURCE_DIR} OUTPUT_VARIABLE changes ERROR_QUIET)
    if(changes)
      string(APPEND commit -dirty)
    endif()
  endif()
endif()
set(text "!> Generated at build time by cmake/slidesim_git_commit.cmake: do not edit.
module app_build_commit
  implicit none (type, external)
  private
  public :: slidesim_git_commit
contains
  !> The git commit the program was built from, or 'unknown'.
  pure function slidesim_git_commit() result(commit)
    character(len=:), allocatable :: commit
    commit = '${commit}'
  end function slidesim_git_commit
end module app_build_commit
")
if(EXISTS ${OUT})
  file(READ ${OUT} old)
endif()
if(NOT old STREQUAL text)
  file(WRITE ${OUT} "${text}")
endif()

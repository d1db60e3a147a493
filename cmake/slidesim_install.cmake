# cmake --install: the slidesim command, the static libraries of every layer and
# fitpack, the Fortran modules (include/slidesim), a CMake package
# (find_package(slidesim) -> slidesim::slidesim) and a pkg-config file (slidesim.pc).
include(CMakePackageConfigHelpers)

get_property(slidesim_layers GLOBAL PROPERTY SLIDESIM_LAYERS)
set(slidesim_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/slidesim)

install(TARGETS slidesim RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS slidesim_library ${slidesim_layers} fitpack EXPORT slidesimTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
# The modules the libraries define, found in their sources (not a folder glob,
# which would take stale or test modules along).
foreach(library IN LISTS slidesim_layers ITEMS fitpack)
  get_target_property(kind ${library} TYPE)
  if(kind STREQUAL "INTERFACE_LIBRARY")
    continue()
  endif()
  get_target_property(sources ${library} SOURCES)
  get_target_property(source_dir ${library} SOURCE_DIR)
  get_target_property(module_dir ${library} Fortran_MODULE_DIRECTORY)
  foreach(source IN LISTS sources)
    if(NOT IS_ABSOLUTE ${source})
      set(source ${source_dir}/${source})
    endif()
    file(STRINGS ${source} lines REGEX "^[ \t]*[Mm][Oo][Dd][Uu][Ll][Ee][ \t]+[A-Za-z_0-9]+[ \t]*$")
    foreach(line IN LISTS lines)
      string(REGEX REPLACE "^[ \t]*[Mm][Oo][Dd][Uu][Ll][Ee][ \t]+([A-Za-z_0-9]+).*" "\\1" module "${line}")
      string(TOLOWER ${module} module)
      install(FILES ${module_dir}/${module}.mod DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/slidesim)
    endforeach()
  endforeach()
endforeach()
install(EXPORT slidesimTargets NAMESPACE slidesim:: DESTINATION ${slidesim_cmake_dir})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/slidesimConfig.cmake.in
  ${PROJECT_BINARY_DIR}/slidesimConfig.cmake INSTALL_DESTINATION ${slidesim_cmake_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/slidesimConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/slidesimConfig.cmake ${PROJECT_BINARY_DIR}/slidesimConfigVersion.cmake
        DESTINATION ${slidesim_cmake_dir})

# pkg-config: the layers from the top (scenarios) down to base, fitpack, then
# the libraries they use (full paths, as CMake found them), MPI's among them
# when slidesim is built with it.
set(pc_libs "")
list(REVERSE slidesim_layers)
foreach(layer IN LISTS slidesim_layers ITEMS fitpack)
  get_target_property(kind ${layer} TYPE)
  if(NOT kind STREQUAL "INTERFACE_LIBRARY")
    string(APPEND pc_libs " -l${layer}")
  endif()
endforeach()
foreach(lib IN LISTS SUNDIALS_FORTRAN_LIBRARIES MINPACK_LIBRARY LAPACK_LIBRARIES HDF5_Fortran_HL_LIBRARIES
                     HDF5_Fortran_LIBRARIES)
  string(APPEND pc_libs " ${lib}")
endforeach()
# MPI (the sweep's ranks, in the design layer): in Libs, not Libs.private or
# Requires.private, because the layers are static archives and a consumer's
# `pkg-config --libs` (without --static) must still link every symbol they
# reach (anything that reaches the scenario registry reaches mpi_send).
if(SLIDESIM_WITH_MPI)
  foreach(flag IN LISTS MPI_Fortran_LINK_FLAGS MPI_Fortran_LIBRARIES)
    string(APPEND pc_libs " ${flag}")
  endforeach()
endif()
string(APPEND pc_libs " ${OpenMP_Fortran_FLAGS}")
if(SLIDESIM_LTO_ON)   # the plain code of the fat LTO objects (README)
  string(APPEND pc_libs " -fno-lto")
endif()
set(pc_cflags "")
foreach(dir IN LISTS SUNDIALS_FORTRAN_MODULE_DIR HDF5_Fortran_INCLUDE_DIRS)
  string(APPEND pc_cflags " -I${dir}")
endforeach()
# relocatable: the prefix is found from the .pc file's own folder
file(RELATIVE_PATH pc_to_prefix ${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR}/pkgconfig ${CMAKE_INSTALL_PREFIX})
string(REGEX REPLACE "/$" "" pc_to_prefix "${pc_to_prefix}")
configure_file(${PROJECT_SOURCE_DIR}/cmake/slidesim.pc.in ${PROJECT_BINARY_DIR}/slidesim.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/slidesim.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

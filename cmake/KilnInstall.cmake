# cmake --install: the kiln tool and its worker, the libraries with their public headers, the
# built-in include library, the shipped materials pack, Kiln.cmake and a KilnConfig.cmake whose
# imported targets are kiln::pack (read packs, pick variants: no Vulkan), kiln::material,
# kiln::runtime, kiln::compiler, and the executables kiln::kiln, kiln::worker and kiln::render. Nothing
# installed names the build or source tree: kiln finds its templates and pack relative to itself
# (docs/install.md).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(KILN_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/Kiln)
set(KILN_INSTALL_DATADIR ${CMAKE_INSTALL_DATADIR}/kiln)

set_target_properties(kiln_base PROPERTIES EXPORT_NAME base)
set_target_properties(kiln_pack PROPERTIES EXPORT_NAME pack)
set_target_properties(kiln_material PROPERTIES EXPORT_NAME material)
set_target_properties(kiln_reference PROPERTIES EXPORT_NAME reference)
set_target_properties(kiln_runtime PROPERTIES EXPORT_NAME runtime)
set_target_properties(kiln_compiler PROPERTIES EXPORT_NAME compiler)
set_target_properties(kiln PROPERTIES EXPORT_NAME kiln)
set_target_properties(kiln-worker PROPERTIES EXPORT_NAME worker)
set_target_properties(kiln-render PROPERTIES EXPORT_NAME render)

foreach(_t kiln_base kiln_pack kiln_material kiln_reference kiln_runtime kiln_compiler)
    target_include_directories(${_t} INTERFACE $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
endforeach()

install(TARGETS kiln_base kiln_pack kiln_material kiln_reference kiln_runtime kiln_compiler
                kiln kiln-worker kiln-render
    EXPORT KilnTargets
    RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
foreach(_inc base/include runtime/include compiler/include)
    install(DIRECTORY ${PROJECT_SOURCE_DIR}/${_inc}/kiln
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.h")
endforeach()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/templates/ DESTINATION ${KILN_INSTALL_DATADIR}/templates)
install(FILES ${CMAKE_BINARY_DIR}/materials/materials.kpack
              ${CMAKE_BINARY_DIR}/materials/materials-half.kpack
        DESTINATION ${KILN_INSTALL_DATADIR})

install(EXPORT KilnTargets NAMESPACE kiln:: DESTINATION ${KILN_INSTALL_CMAKEDIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/KilnConfig.cmake.in
    ${CMAKE_CURRENT_BINARY_DIR}/KilnConfig.cmake
    INSTALL_DESTINATION ${KILN_INSTALL_CMAKEDIR}
    PATH_VARS KILN_INSTALL_DATADIR)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/KilnConfigVersion.cmake
    COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/KilnConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/KilnConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/Kiln.cmake
    DESTINATION ${KILN_INSTALL_CMAKEDIR})

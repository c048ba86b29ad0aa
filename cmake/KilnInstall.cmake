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

# One export set per component, so a consumer that asks for COMPONENTS pack needs only pack's
# dependencies (xxhash): pack (kiln_base, kiln_pack), material, runtime (kiln_reference,
# kiln_runtime), compiler. The executables are a set of their own that every configuration
# imports: an imported executable needs none of the libraries it was linked with.
set(_kiln_component_targets_pack kiln_base kiln_pack)
set(_kiln_component_targets_material kiln_material)
set(_kiln_component_targets_runtime kiln_reference kiln_runtime)
set(_kiln_component_targets_compiler kiln_compiler)
set(_kiln_component_targets_tools kiln kiln-worker kiln-render)
foreach(_c pack material runtime compiler tools)
    string(SUBSTRING ${_c} 0 1 _first)
    string(TOUPPER ${_first} _first)
    string(SUBSTRING ${_c} 1 -1 _rest)
    install(TARGETS ${_kiln_component_targets_${_c}}
        EXPORT Kiln${_first}${_rest}Targets
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
    install(EXPORT Kiln${_first}${_rest}Targets NAMESPACE kiln::
        DESTINATION ${KILN_INSTALL_CMAKEDIR})
endforeach()

# pkg-config files of the libraries (kiln-pack.pc, ...), each requiring the one below it; with
# `--static` they list the system libraries each links.
set(_kiln_pc_pack_libs "-lkiln_pack -lkiln_base")
set(_kiln_pc_pack_requires "libxxhash")
set(_kiln_pc_material_libs "-lkiln_material")
set(_kiln_pc_material_requires "kiln-pack = ${PROJECT_VERSION}")
set(_kiln_pc_runtime_libs "-lkiln_runtime -lkiln_reference")
set(_kiln_pc_runtime_requires
    "kiln-material = ${PROJECT_VERSION}, glm, vulkan, OpenColorIO, tinygltf, libjpeg")
set(_kiln_pc_runtime_private_libs "-lstb -lSPIRV-Tools")
set(_kiln_pc_compiler_libs "-lkiln_compiler")
set(_kiln_pc_compiler_requires "kiln-pack = ${PROJECT_VERSION}")
set(_kiln_pc_compiler_private_libs
    "-lglslang -lSPIRV -lglslang-default-resource-limits -lSPIRV-Tools-opt -lSPIRV-Tools -lspirv-cross-msl -lspirv-cross-hlsl -lspirv-cross-glsl -lspirv-cross-core -lpthread")
file(RELATIVE_PATH KILN_PC_PREFIX_FROM_PCFILEDIR
    /root/${CMAKE_INSTALL_LIBDIR}/pkgconfig /root)  # "../.." for lib/pkgconfig
string(REGEX REPLACE "/$" "" KILN_PC_PREFIX_FROM_PCFILEDIR "${KILN_PC_PREFIX_FROM_PCFILEDIR}")
foreach(_c pack material runtime compiler)
    set(KILN_PC_NAME kiln-${_c})
    set(KILN_PC_LIBS ${_kiln_pc_${_c}_libs})
    set(KILN_PC_REQUIRES ${_kiln_pc_${_c}_requires})
    set(KILN_PC_PRIVATE_LIBS "${_kiln_pc_${_c}_private_libs}")
    configure_file(${PROJECT_SOURCE_DIR}/cmake/kiln.pc.in
        ${CMAKE_CURRENT_BINARY_DIR}/pkgconfig/kiln-${_c}.pc @ONLY)
    install(FILES ${CMAKE_CURRENT_BINARY_DIR}/pkgconfig/kiln-${_c}.pc
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
endforeach()

foreach(_inc base/include runtime/include compiler/include)
    install(DIRECTORY ${PROJECT_SOURCE_DIR}/${_inc}/kiln
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.h")
endforeach()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/templates/ DESTINATION ${KILN_INSTALL_DATADIR}/templates)
install(FILES ${CMAKE_BINARY_DIR}/materials/materials.kpack
              ${CMAKE_BINARY_DIR}/materials/materials-half.kpack
        DESTINATION ${KILN_INSTALL_DATADIR})

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

# cmake --install --strip: CMake strips the executables; the static libraries lose their debug
# information too (--strip-debug keeps every symbol a consumer's linker needs). docs/install.md
# states the size of a stripped install.
set(_kiln_static_libs ${_kiln_component_targets_pack} ${_kiln_component_targets_material}
    ${_kiln_component_targets_runtime} ${_kiln_component_targets_compiler})
install(CODE "
if(CMAKE_INSTALL_DO_STRIP)
    foreach(_lib ${_kiln_static_libs})
        execute_process(COMMAND \"${CMAKE_STRIP}\" --strip-debug
            \"\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR}/lib\${_lib}.a\"
            RESULT_VARIABLE _rc)
        if(NOT _rc EQUAL 0)
            message(FATAL_ERROR \"cannot strip lib\${_lib}.a\")
        endif()
    endforeach()
endif()")

# kiln_compile_materials(TARGET <name> OUTPUT <pack> SOURCES <a.shader>...
#                        [INCLUDE_DIRS <dir>...] [KEYWORDS <kw>...] [OPTIONS <flag>...]
#                        [MATERIALS <x.material or scene.kiln.json>...]
#                        [KILN <kiln executable or target>])
#
# Compiles .shader files into one variant pack at build time. Kiln writes a depfile of every file
# it read (the shaders and every #include), so editing an included .cginc rebuilds the pack, and
# an unchanged build does not run kiln at all. shader_feature variants are built as Unity builds
# them: the all-off combination and the combinations the MATERIALS enable (OPTIONS --all-features
# builds every one). Adds a custom target <name> that builds the pack
# (ALL unless EXCLUDE_FROM_ALL is given).
function(kiln_compile_materials)
    cmake_parse_arguments(ARG "EXCLUDE_FROM_ALL" "TARGET;OUTPUT;KILN"
        "SOURCES;INCLUDE_DIRS;KEYWORDS;OPTIONS;MATERIALS" ${ARGN})
    if(NOT ARG_TARGET OR NOT ARG_OUTPUT OR NOT ARG_SOURCES)
        message(FATAL_ERROR "kiln_compile_materials: TARGET, OUTPUT and SOURCES are required")
    endif()
    if(NOT ARG_KILN)
        set(ARG_KILN kiln)
    endif()
    if(TARGET ${ARG_KILN})
        set(_kiln $<TARGET_FILE:${ARG_KILN}>)
        set(_kiln_dep ${ARG_KILN})
    else()
        set(_kiln ${ARG_KILN})
        set(_kiln_dep "")
    endif()
    cmake_path(ABSOLUTE_PATH ARG_OUTPUT BASE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}
        NORMALIZE OUTPUT_VARIABLE _out)
    set(_sources "")
    foreach(_s IN LISTS ARG_SOURCES)
        cmake_path(ABSOLUTE_PATH _s BASE_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}
            NORMALIZE OUTPUT_VARIABLE _abs)
        list(APPEND _sources ${_abs})
    endforeach()
    set(_args "")
    foreach(_i IN LISTS ARG_INCLUDE_DIRS)
        cmake_path(ABSOLUTE_PATH _i BASE_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}
            NORMALIZE OUTPUT_VARIABLE _abs)
        list(APPEND _args -I ${_abs})
    endforeach()
    if(ARG_KEYWORDS)
        list(JOIN ARG_KEYWORDS "," _kw)
        list(APPEND _args --keywords ${_kw})
    endif()
    set(_materials "")
    foreach(_m IN LISTS ARG_MATERIALS)
        cmake_path(ABSOLUTE_PATH _m BASE_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}
            NORMALIZE OUTPUT_VARIABLE _abs)
        list(APPEND _materials ${_abs})
        list(APPEND _args --materials ${_abs})
    endforeach()
    list(APPEND _args ${ARG_OPTIONS})
    add_custom_command(
        OUTPUT ${_out}
        COMMAND ${_kiln} compile ${_sources} -o ${_out} -MD -MF ${_out}.d ${_args}
        DEPENDS ${_sources} ${_materials} ${_kiln_dep}
        DEPFILE ${_out}.d
        COMMENT "Compiling Kiln materials into ${ARG_OUTPUT}"
        VERBATIM)
    if(ARG_EXCLUDE_FROM_ALL)
        add_custom_target(${ARG_TARGET} DEPENDS ${_out})
    else()
        add_custom_target(${ARG_TARGET} ALL DEPENDS ${_out})
    endif()
    set_target_properties(${ARG_TARGET} PROPERTIES KILN_PACK ${_out})
endfunction()

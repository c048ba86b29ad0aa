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
#
# KILN: the kiln target in Kiln's own build, else kiln::kiln from find_package(Kiln), else the
# kiln program on PATH (an error when there is none). The pack depends on the kiln binary, so
# upgrading Kiln rebuilds it. The output's folder is created; Ninja and Unix Makefiles both work.
function(kiln_compile_materials)
    cmake_parse_arguments(ARG "EXCLUDE_FROM_ALL" "TARGET;OUTPUT;KILN"
        "SOURCES;INCLUDE_DIRS;KEYWORDS;OPTIONS;MATERIALS" ${ARGN})
    if(NOT ARG_TARGET OR NOT ARG_OUTPUT OR NOT ARG_SOURCES)
        message(FATAL_ERROR "kiln_compile_materials: TARGET, OUTPUT and SOURCES are required")
    endif()
    if(NOT ARG_KILN)
        if(TARGET kiln)
            set(ARG_KILN kiln)
        elseif(TARGET kiln::kiln)
            set(ARG_KILN kiln::kiln)
        else()
            find_program(KILN_EXECUTABLE kiln)
            if(NOT KILN_EXECUTABLE)
                message(FATAL_ERROR "kiln_compile_materials: no kiln: find_package(Kiln) first, "
                    "pass KILN <path>, or put kiln on PATH")
            endif()
            set(ARG_KILN ${KILN_EXECUTABLE})
        endif()
    endif()
    if(TARGET ${ARG_KILN})
        set(_kiln $<TARGET_FILE:${ARG_KILN}>)
        get_target_property(_imported ${ARG_KILN} IMPORTED)
        if(_imported)
            set(_kiln_dep $<TARGET_FILE:${ARG_KILN}>)  # file-level: a new kiln rebuilds packs
        else()
            set(_kiln_dep ${ARG_KILN})  # target- and file-level
        endif()
    else()
        cmake_path(ABSOLUTE_PATH ARG_KILN NORMALIZE OUTPUT_VARIABLE _kiln)
        if(NOT EXISTS ${_kiln})
            find_program(_kiln_found NAMES ${ARG_KILN} NO_CACHE)
            if(NOT _kiln_found)
                message(FATAL_ERROR "kiln_compile_materials: KILN '${ARG_KILN}' not found")
            endif()
            set(_kiln ${_kiln_found})
        endif()
        set(_kiln_dep ${_kiln})
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
    cmake_path(GET _out PARENT_PATH _out_dir)
    add_custom_command(
        OUTPUT ${_out}
        COMMAND ${CMAKE_COMMAND} -E make_directory ${_out_dir}
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

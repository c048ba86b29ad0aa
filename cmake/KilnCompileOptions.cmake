# Warning and sanitizer flags shared by every Kiln target: call kiln_target_options(<target>).

# Debug info and __FILE__ name the build folder as ".": an installed Kiln does not point back at
# the tree it was built in (tests/install checks).
add_compile_options(-ffile-prefix-map=${CMAKE_BINARY_DIR}=.)

if(KILN_SANITIZE)
    string(REPLACE "," ";" _kiln_sanitizers "${KILN_SANITIZE}")
    foreach(_s IN LISTS _kiln_sanitizers)
        if(NOT _s MATCHES "^(address|undefined|leak|thread)$")
            message(FATAL_ERROR "KILN_SANITIZE: unknown sanitizer '${_s}'")
        endif()
    endforeach()
    set(_kiln_san_flags -fsanitize=${KILN_SANITIZE} -fno-omit-frame-pointer
        -fno-sanitize-recover=all)
    if("undefined" IN_LIST _kiln_sanitizers)
        # Debian's glslang is built without RTTI for TShader: UBSan's vptr check cannot link.
        list(APPEND _kiln_san_flags -fno-sanitize=vptr)
    endif()
    add_compile_options(${_kiln_san_flags})
    add_link_options(${_kiln_san_flags})
endif()

if(KILN_FUZZ)
    # Coverage instrumentation for everything, so libFuzzer sees inside the libraries too; only
    # the fuzz targets themselves link libFuzzer's main (-fsanitize=fuzzer).
    add_compile_options(-fsanitize=fuzzer-no-link)
endif()

function(kiln_target_options target)
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow
        -Wnon-virtual-dtor -Wconversion -Wno-sign-conversion)
    if(KILN_WERROR)
        target_compile_options(${target} PRIVATE -Werror)
    endif()
endfunction()

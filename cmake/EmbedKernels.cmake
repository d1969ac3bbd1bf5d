# Embeds the OpenCL sources under kernels/ into the library as a table of
# (relative path, text) pairs, so an installed prism needs no source tree.
# Each file becomes one raw string literal split in chunks, which keeps every
# literal well under compiler limits.
function(prism_embed_kernels output root)
  set(files ${ARGN})
  add_custom_command(
    OUTPUT ${output}
    COMMAND ${CMAKE_COMMAND} -DOUTPUT=${output} -DROOT=${root} "-DFILES=${files}"
            -P ${CMAKE_SOURCE_DIR}/cmake/EmbedKernelsScript.cmake
    DEPENDS ${files} ${CMAKE_SOURCE_DIR}/cmake/EmbedKernelsScript.cmake
    COMMENT "Embedding OpenCL kernel sources"
    VERBATIM)
endfunction()

# The built-in models that assets/models/make_models.py writes (builtin:boat
# is its boat.gltf; the fleet's fleet/*.gltf are builtin:tug and the others),
# embedded into one generated C++ source (embeddedModelFiles()): one source
# for the file a user may place and the built-in. Used by the library and by
# the fuzzers, whose scene checks read the fleet's design numbers.
#   swell_embedded_models(OUTPUT_FILE ROOT_DIR)
function(swell_embedded_models output root)
  file(GLOB fleet_models RELATIVE ${root}/assets/models CONFIGURE_DEPENDS ${root}/assets/models/fleet/*.gltf)
  list(SORT fleet_models)
  set(files boat.gltf ${fleet_models})
  list(TRANSFORM fleet_models PREPEND ${root}/assets/models/ OUTPUT_VARIABLE fleet_model_paths)
  string(REPLACE ";" "," file_list "${files}")
  add_custom_command(OUTPUT ${output}
    COMMAND ${CMAKE_COMMAND} -DOUTPUT=${output} -DBASE_DIR=${root}/assets/models
            -DFILES=${file_list} -DFUNCTION=embeddedModelFiles -P ${root}/cmake/EmbedFiles.cmake
    DEPENDS ${root}/assets/models/boat.gltf ${fleet_model_paths} ${root}/cmake/EmbedFiles.cmake
    COMMENT "Embedding built-in models" VERBATIM)
endfunction()

# Unity builds by folder (docs/build-time.md has the measurements). Most of a translation unit's
# cost here is the headers every file of a folder shares (GLM, the standard library, CLI11 in
# cli/, nlohmann in scene/), so compiling a folder's files as one unit parses them once: the
# library's clean build drops from ~5 to ~2 CPU minutes. Grouping by folder keeps the include
# rules' boundaries (tools/check_include_rules.py): a unit holds one stage's files, so a file can
# only see headers its own stage may include; files the rules single out for a third-party header
# are compiled ALONE. -DSWEEPTRACE_UNITY=OFF compiles every file by itself (the sanitizer build
# does, so a file that compiles only thanks to a neighbour's include fails there).

# sweeptrace_unity_by_folder(TARGET BASE_DIR [ALONE source...]): one unit per folder under
# BASE_DIR of TARGET's sources, except the ALONE sources and generated ones.
function(sweeptrace_unity_by_folder target base)
  if(NOT SWEEPTRACE_UNITY)
    return()
  endif()
  cmake_parse_arguments(PARSE_ARGV 2 U "" "" "ALONE")
  set(alone)
  foreach(src IN LISTS U_ALONE)
    get_filename_component(abs ${src} ABSOLUTE BASE_DIR ${CMAKE_CURRENT_SOURCE_DIR})
    list(APPEND alone ${abs})
  endforeach()
  set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_MODE GROUP)
  get_target_property(sources ${target} SOURCES)
  foreach(src IN LISTS sources)
    get_filename_component(abs ${src} ABSOLUTE BASE_DIR ${CMAKE_CURRENT_SOURCE_DIR})
    if(abs IN_LIST alone OR NOT abs MATCHES "\\.cpp$")
      continue()
    endif()
    file(RELATIVE_PATH rel ${base} ${abs})
    if(rel MATCHES "^\\.\\.")
      continue()  # generated (program_version.cpp in the build tree)
    endif()
    get_filename_component(dir ${rel} DIRECTORY)
    string(MAKE_C_IDENTIFIER "${target}_${dir}" group)
    set_source_files_properties(${src} PROPERTIES UNITY_GROUP ${group})
  endforeach()
endfunction()

# sweeptrace_unity_batches(TARGET SIZE [ALONE name...]): TARGET's sources in units of SIZE
# files (the test binaries: a folder of tests is too big for one unit on 2 cores), except the
# sources whose file names are listed ALONE. Batches shift as files are added,
# so names at file scope (anonymous namespaces, statics) must be unique across the target.
function(sweeptrace_unity_batches target size)
  if(NOT SWEEPTRACE_UNITY)
    return()
  endif()
  cmake_parse_arguments(PARSE_ARGV 2 U "" "" "ALONE")
  set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_MODE BATCH UNITY_BUILD_BATCH_SIZE ${size})
  get_target_property(sources ${target} SOURCES)
  foreach(src IN LISTS sources)
    get_filename_component(name ${src} NAME)
    if(name IN_LIST U_ALONE)
      set_source_files_properties(${src} PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
    endif()
  endforeach()
endfunction()

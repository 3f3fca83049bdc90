# Reads the layer table (engine/layers.txt) into variables for every directory below the top one:
#   CANDELA_LAYERS                      the folders, in the table's order
#   CANDELA_LAYER_<folder>_TARGET       the folder's CMake target
#   CANDELA_LAYER_<folder>_KIND         cpu, device or viewer
#   CANDELA_LAYER_<folder>_PUBLIC       the targets it links PUBLIC (its headers include them)
#   CANDELA_LAYER_<folder>_PRIVATE      ... and PRIVATE
# A row that links a folder not above it, or a malformed row, stops the configure step.
set(CANDELA_LAYER_TABLE ${CMAKE_CURRENT_LIST_DIR}/layers.txt)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${CANDELA_LAYER_TABLE})
file(STRINGS ${CANDELA_LAYER_TABLE} candela_layer_rows REGEX "^[a-z]")
set(CANDELA_LAYERS "")
foreach(row IN LISTS candela_layer_rows)
  string(REGEX MATCHALL "[^ \t]+" fields "${row}")
  list(LENGTH fields count)
  if(count LESS 5)
    message(FATAL_ERROR "engine/layers.txt: '${row}': expected folder, target, namespace, kind and links")
  endif()
  list(POP_FRONT fields folder target namespace kind)  # the namespace: tools/check_layers.py
  if(NOT kind MATCHES "^(cpu|device|viewer)$")
    message(FATAL_ERROR "engine/layers.txt: ${folder}: kind '${kind}' is none of cpu, device, viewer")
  endif()
  set(CANDELA_LAYER_${folder}_TARGET ${target})
  set(CANDELA_LAYER_${folder}_KIND ${kind})
  set(CANDELA_LAYER_${folder}_PUBLIC "")
  set(CANDELA_LAYER_${folder}_PRIVATE "")
  set(visibility PUBLIC)
  foreach(field IN LISTS fields)
    if(field STREQUAL "|")
      set(visibility PRIVATE)
    elseif(NOT field STREQUAL "-")
      if(NOT field IN_LIST CANDELA_LAYERS)
        message(FATAL_ERROR "engine/layers.txt: ${folder} links ${field}, which is not a row above it")
      endif()
      list(APPEND CANDELA_LAYER_${folder}_${visibility} ${CANDELA_LAYER_${field}_TARGET})
    endif()
  endforeach()
  list(APPEND CANDELA_LAYERS ${folder})
endforeach()

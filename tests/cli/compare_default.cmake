# `penumbra compare` on the default scene (small size to keep the suite fast): a table on
# stdout and the files a person wants to look at.
file(REMOVE_RECURSE "${OUT}")
execute_process(COMMAND "${PENUMBRA}" compare --size 320x180 --timed-frames 1 --out "${OUT}"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "penumbra compare exited with ${rc}: ${err}")
endif()
foreach(f compare.json reference.png side_by_side.png hard.png hard_heat.png none.png none_heat.png)
  if(NOT EXISTS "${OUT}/${f}")
    message(FATAL_ERROR "missing ${OUT}/${f}")
  endif()
endforeach()
file(READ "${OUT}/compare.json" j)
string(JSON hard_wrong GET "${j}" techniques 0 wrong_pixel_share)
string(JSON none_wrong GET "${j}" techniques 1 wrong_pixel_share)
if(NOT hard_wrong LESS none_wrong)
  message(FATAL_ERROR "hard (${hard_wrong}) should beat no shadows (${none_wrong})")
endif()
if(NOT out MATCHES "technique +RMSE +wrong %")
  message(FATAL_ERROR "no table printed")
endif()

# Variants side by side: msm with and without its mip levels, each row labelled, its own parameters
# in the JSON, its own files; the variant's score differs from the plain technique's.
execute_process(COMMAND "${PENUMBRA}" compare --techniques msm,msm:mipmaps=false --size 320x180 --timed-frames 1 --out "${OUT}/variants"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "penumbra compare with a variant exited with ${rc}: ${err}")
endif()
file(READ "${OUT}/variants/compare.json" j)
string(JSON plain_label GET "${j}" techniques 0 label)
string(JSON variant_label GET "${j}" techniques 1 label)
string(JSON variant_technique GET "${j}" techniques 1 technique)
string(JSON variant_mipmaps GET "${j}" techniques 1 parameters mipmaps)
string(JSON plain_rmse GET "${j}" techniques 0 rmse)
string(JSON variant_rmse GET "${j}" techniques 1 rmse)
if(NOT plain_label STREQUAL "msm" OR NOT variant_label STREQUAL "msm:mipmaps=false" OR NOT variant_technique STREQUAL "msm"
   OR NOT variant_mipmaps STREQUAL "false" OR plain_rmse EQUAL variant_rmse)
  message(FATAL_ERROR "variant rows: '${plain_label}' ${plain_rmse}, '${variant_label}' (${variant_technique}, mipmaps ${variant_mipmaps}) ${variant_rmse}")
endif()
if(NOT EXISTS "${OUT}/variants/msm_mipmaps_false.png" OR NOT EXISTS "${OUT}/variants/msm_mipmaps_false_heat.png" OR NOT out MATCHES "msm:mipmaps=false +0\\.")
  message(FATAL_ERROR "the variant's files or its row are missing:\n${out}")
endif()

# --behind-glass scores the surface seen through the default scene's pane, and says so where a
# view holds no glass (the zeros it prints then are not a score).
execute_process(COMMAND "${PENUMBRA}" compare --behind-glass --techniques hard --size 160x90 --timed-frames 1 --out "${OUT}/behind"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "penumbra compare --behind-glass exited with ${rc}: ${err}")
endif()
file(READ "${OUT}/behind/compare.json" j)
string(JSON surfaces GET "${j}" surfaces)
string(JSON behind_pixels GET "${j}" techniques 0 compared_pixels)
if(NOT surfaces STREQUAL "behind glass" OR NOT behind_pixels GREATER 100)
  message(FATAL_ERROR "--behind-glass scored '${surfaces}' on ${behind_pixels} pixels; the default scene's pane shows more")
endif()
file(WRITE "${OUT}/no_glass.json" [=[{ "lights": [ { "type": "directional", "direction": [0.3, -1, 0.2] } ],
  "objects": [ { "shape": "plane", "size": [8, 8] }, { "shape": "box", "position": [0, 0.5, 0] } ] }]=])
execute_process(COMMAND "${PENUMBRA}" compare "${OUT}/no_glass.json" --behind-glass --techniques hard --size 64x36 --timed-frames 1
  --out "${OUT}/no_glass" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT err MATCHES "no pixel's nearest surface is translucent")
  message(FATAL_ERROR "--behind-glass without glass in view: exit ${rc}, stderr '${err}'")
endif()

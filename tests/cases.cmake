# Shell-driven tests: they run installed applications and out-of-tree builds, which a
# GoogleTest executable linked into the build tree cannot exercise.

# The user-plugin example: install this build, build tutorials/plugins/myMaterial against
# the exported package, run tutorials/plugins/viscoElasticBar (tests/scripts/pluginExample.sh).
add_test(NAME pluginExample
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/scripts/pluginExample.sh
                 ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR})
# The same cmake and compiler as this build, so the plugin's ABI matches the libraries.
set_tests_properties(pluginExample PROPERTIES
  TIMEOUT 600
  LABELS integration
  ENVIRONMENT "CMAKE=${CMAKE_COMMAND};CXX=${CMAKE_CXX_COMPILER}")

# A contact law and a rigid-body driver from a user's library built out of tree
# (tests/support/scenePlugin), run in one scene against analytic checks.
add_test(NAME scenePlugin
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/scripts/scenePlugin.sh ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR})
set_tests_properties(scenePlugin PROPERTIES TIMEOUT 600 LABELS integration
  ENVIRONMENT "CMAKE=${CMAKE_COMMAND};CXX=${CMAKE_CXX_COMPILER}")

# The dictionary parser under libFuzzer with sanitizers, a fixed number of inputs (seconds);
# a long run for developers: tests/scripts/fuzzDictionary.sh . 5000000
add_test(NAME fuzzDictionary
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/scripts/fuzzDictionary.sh ${PROJECT_SOURCE_DIR} 20000)
set_tests_properties(fuzzDictionary PROPERTIES TIMEOUT 600 LABELS integration)

# Code, headers and user guide agree on the keywords (etc/python/keywordTables.py): every
# keyword the code reads is in a table of doc/userGuide with its default, every keyword
# there is read, and each registered type's header table is the guide's table for it.
add_test(NAME keywordDrift COMMAND python3 ${PROJECT_SOURCE_DIR}/etc/python/keywordTables.py check ${PROJECT_SOURCE_DIR})
set_tests_properties(keywordDrift PROPERTIES TIMEOUT 60 ENVIRONMENT "PYTHONDONTWRITEBYTECODE=1")
# picToC -keywords TYPE prints those tables; an unknown type is one line (tests/scripts/picToCKeywords.sh).
add_test(NAME picToCKeywords
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/scripts/picToCKeywords.sh ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR})
set_tests_properties(picToCKeywords PROPERTIES TIMEOUT 120 ENVIRONMENT "PYTHONDONTWRITEBYTECODE=1")

# Every script a user runs answers -help, --help and -h alike, from a scratch copy
# (tests/scripts/scriptsHelp.sh): the Allrun, Allclean, Allvalidate, bench/run, picStudy.
add_test(NAME scriptsHelp
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/scripts/scriptsHelp.sh ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR})
set_tests_properties(scriptsHelp PROPERTIES TIMEOUT 120)

# The ParaView scripts (etc/paraview, each tutorial's paraviewParticles.py) at least compile:
# ParaView itself cannot be installed beside the build's VTK (doc/userGuide/output.md,
# "Output for ParaView").
file(GLOB PARAVIEW_SCRIPTS ${PROJECT_SOURCE_DIR}/etc/paraview/*.py ${PROJECT_SOURCE_DIR}/tutorials/*/*/paraviewParticles.py)
add_test(NAME paraviewScripts COMMAND python3 -m py_compile ${PARAVIEW_SCRIPTS})
set_tests_properties(paraviewScripts PROPERTIES TIMEOUT 60 ENVIRONMENT "PYTHONPYCACHEPREFIX=${CMAKE_CURRENT_BINARY_DIR}/pycache")

# Each tutorial's Allrun must print its error-against-run-time table and write its plots.
foreach(tutorial "verification/elasticBar;bar.png;error.png"
                 "verification/twoDisks;energy.png;error.png"
                 "contact/inclinedDisk;displacement.png;error.png"
                 "contact/inclinedSphere;displacement.png;error.png"
                 "contact/frictionalDisks;energy.png;error.png"
                 "verification/impact;depth.png;error.png"
                 "verification/elasticFooting;stress.png;error.png"
                 "verification/thickCylinder;stress.png;error.png"
                 "verification/thickSphere;stress.png;error.png"
                 "verification/circularPunch;pressure.png;error.png"
                 "earthmoving/circularSilo;mass.png;error.png"
                 "earthmoving/circularSilo3D;mass.png;error.png"
                 "verification/plungerOedometer;force.png;stressPath.png;error.png"
                 "geotechnics/footingBearing;pressure.png;error.png"
                 "geotechnics/circularFooting;pressure.png;error.png"
                 "geotechnics/verticalCut;pressure.png;error.png"
                 "geotechnics/blade;force.png;depth.png;error.png"
                 "geotechnics/bladeWidth;force.png;width.png;error.png"
                 "geotechnics/retainingWall;force.png;error.png"
                 "geotechnics/stripFooting;pressure.png;error.png"
                 "geotechnics/anchors;load.png;error.png"
                 "earthmoving/cornBlade;force.png;error.png"
                 "earthmoving/cornBladeTurned;band.png;force.png"
                 "earthmoving/bucket;force.png;error.png;bucket.png"
                 "earthmoving/bucket3D;force.png;parts.png;fill.png"
                 "earthmoving/silos;mass.png;layers-end.png;error.png"
                 "materials/oedometerPoint;oedometer.png"
                 "materials/muIPoint;muI.png"
                 "verification/chuteFlow;profile.png"
                 "verification/muISilo;mass.png"
                 "geotechnics/silo;flowRate.png;flowPattern-0.2.png;error.png"
                 "geotechnics/columnCollapse;deposit.png"
                 "geotechnics/muIColumnCollapse;runout.png;deposit.png"
                 "geotechnics/cylinderCollapse;deposit.png"
                 "verification/stlVolumes;error.png"
                 "studies/bladeDepthFriction;force.png;error.png"
                 "studies/bucketGeometry;studies/bucketGeometry/plots/carried-toothLength.png;studies/bucketGeometry/plots/toothWear-toothAngle.png")
  list(GET tutorial 0 path)
  if(NOT GPIC_WITH_3D AND (path STREQUAL "geotechnics/cylinderCollapse" OR path STREQUAL "verification/stlVolumes"
                           OR path STREQUAL "contact/inclinedSphere" OR path STREQUAL "earthmoving/circularSilo3D"
                           OR path STREQUAL "geotechnics/bladeWidth" OR path STREQUAL "earthmoving/bucket3D"))
    continue()  # a 3D case: a plane build refuses it
  endif()
  list(SUBLIST tutorial 1 -1 plots)
  string(REPLACE "/" "_" name "tutorial_${path}")
  add_test(NAME ${name}
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/scripts/tutorialRun.sh
                   ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR} ${path} ${plots})
  set_tests_properties(${name} PROPERTIES TIMEOUT 600 LABELS integration)
endforeach()

# The validation report generator (tutorials/Allvalidate) on two quick tutorials.
add_test(NAME validationReport
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/scripts/validationReport.sh
                 ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR})
set_tests_properties(validationReport PROPERTIES TIMEOUT 600 LABELS integration)

# The benchmark script and its scenes, a few steps each (bench/run -quick).
add_test(NAME benchQuick
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/scripts/benchQuick.sh
                 ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR})
set_tests_properties(benchQuick PROPERTIES TIMEOUT 600 LABELS integration)

# A file-size limit and a closed output pipe (tests/scripts/writeLimits.sh).
add_test(NAME writeLimits
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/scripts/writeLimits.sh ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR})
set_tests_properties(writeLimits PROPERTIES TIMEOUT 300 LABELS integration)

# Mass scaling against the unscaled run on the seed's anchor (tests/scripts/massScaling.sh).
add_test(NAME massScalingAnchor
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/scripts/massScaling.sh ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR})
set_tests_properties(massScalingAnchor PROPERTIES TIMEOUT 600 LABELS integration)

# Design studies (picStudy, etc/python/picstudy) on a four-case blade study pushed 2 mm:
# the dry run's case files line by line, bad studyDicts, resuming and a failed case, and
# local against Slurm (a one-node cluster the test starts: tests/scripts/slurmLocal.sh).
foreach(study studyDryRun studyBadInput studyBadBytes studyResume studyLocalSlurm)
  add_test(NAME ${study}
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/scripts/${study}.sh ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR})
  set_tests_properties(${study} PROPERTIES TIMEOUT 300 LABELS integration)
endforeach()
# Slurm's daemons want the machine's cores: not beside another test that would take them.
set_tests_properties(studyLocalSlurm PROPERTIES RUN_SERIAL TRUE)

# picDecompose and picReconstruct: the round trip of a plane and a 3D case by each method
# (tests/scripts/decomposeReconstruct.sh).
add_test(NAME decomposeReconstruct
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/scripts/decomposeReconstruct.sh ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR})
set_tests_properties(decomposeReconstruct PROPERTIES TIMEOUT 300 LABELS integration)

# picSolver -parallel under mpirun against the serial run, a plane and a 3D case
# (tests/scripts/parallelRun.sh; oversubscribed on the 2-core CI machine).
if(GPIC_WITH_MPI AND GPIC_WITH_3D)
  add_test(NAME parallelRun
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/scripts/parallelRun.sh ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR})
  set_tests_properties(parallelRun PROPERTIES TIMEOUT 600 LABELS integration)
endif()

# One writer per case: a second run refused, a stale lock taken over (tests/scripts/caseLock.sh).
add_test(NAME caseLock
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/scripts/caseLock.sh ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR})
set_tests_properties(caseLock PROPERTIES TIMEOUT 300 LABELS integration)

# Allocations beyond ulimit -v named with their size (tests/scripts/memoryLimits.sh).
add_test(NAME memoryLimits
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/scripts/memoryLimits.sh ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR})
set_tests_properties(memoryLimits PROPERTIES TIMEOUT 300 LABELS integration)

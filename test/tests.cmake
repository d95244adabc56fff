# Tests: gtest on the ROS-free core, rostest on the node. Run by scripts/test.sh (README).
find_package(rostest REQUIRED)

catkin_add_gtest(physics_tests
  test/physics/test_polynomial.cpp
  test/physics/test_motion.cpp
  test/physics/test_slate_bounce.cpp
  test/physics/test_airborne.cpp
  test/physics/test_resting_contact.cpp
  test/physics/test_orientation.cpp
  test/physics/test_collisions.cpp
  test/physics/test_cushion_models.cpp
  test/physics/test_ball_ball_models.cpp
  test/physics/test_tangential_compliance.cpp
  test/physics/test_engine.cpp
  test/physics/test_shot_physics.cpp
  test/physics/test_stability.cpp
  test/physics/test_frozen_contacts.cpp
  test/physics/test_golden.cpp
  test/physics/test_batch.cpp
  test/physics/test_execution_noise.cpp
  test/physics/test_cue_aim.cpp
  test/physics/test_cue_sweep.cpp
  test/physics/test_event_search.cpp
  test/physics/test_simulation.cpp
  test/physics/test_physics_params.cpp
)
target_link_libraries(physics_tests cue_sim_physics gtest_main)
# The event search's internal structures are tested on their own too.
target_include_directories(physics_tests PRIVATE src)
target_compile_definitions(physics_tests PRIVATE CUE_SIM_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
# The second longest (1 to 2 minutes): early, beside the others.
set_tests_properties(_ctest_cue_sim_gtest_physics_tests PROPERTIES COST 500)

catkin_add_gtest(game_tests test/game/test_referee.cpp test/game/test_ten_ball.cpp test/game/test_three_cushion.cpp
                 test/game/test_snooker.cpp)
target_link_libraries(game_tests cue_sim_game gtest_main)

catkin_add_gtest(accuracy_tests test/physics/test_accuracy.cpp)
target_link_libraries(accuracy_tests cue_sim_evaluation gtest_main)

catkin_add_gtest(evaluation_tests test/evaluation/test_soak.cpp)
target_link_libraries(evaluation_tests cue_sim_soak gtest_main)
# When a campaign's shot must have ended (src/evaluation/soak/shot_ending.hpp) is tested on its own too.
target_include_directories(evaluation_tests PRIVATE src)
target_compile_definitions(evaluation_tests PRIVATE CUE_SIM_SOURCE_DIR="${PROJECT_SOURCE_DIR}")

catkin_add_gtest(scene_tests
  test/scene/test_urdf_table.cpp
  test/scene/test_scene_file.cpp
  test/scene/test_simulate_program.cpp
  test/scene/test_bundled_tables.cpp
  test/scene/test_model_registry.cpp
  test/scene/test_ball_colours.cpp
)
target_link_libraries(scene_tests cue_sim_table_description gtest_main)
target_compile_definitions(scene_tests PRIVATE
  CUE_SIM_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
  CUE_SIM_SIMULATE="$<TARGET_FILE:simulate>"
  CUE_SIM_SELF_PLAY="$<TARGET_FILE:self_play>")
add_dependencies(scene_tests simulate self_play)

catkin_add_gtest(session_tests test/session/test_live_table.cpp test/session/test_live_game.cpp test/session/test_live_parts.cpp test/session/test_shot_preview.cpp
  test/session/test_ball_orientations.cpp test/session/test_cue_follower.cpp)
target_link_libraries(session_tests cue_sim_session cue_sim_table_description gtest_main)

catkin_add_gtest(camera_tests test/camera/test_table_camera.cpp)
target_link_libraries(camera_tests cue_sim_camera gtest_main)

add_rostest_gtest(node_tests test/node/table_node.test test/node/test_table_node.cpp test/node/rostest_main.cpp)
target_include_directories(node_tests PRIVATE ${catkin_INCLUDE_DIRS})
target_link_libraries(node_tests ${catkin_LIBRARIES})
add_dependencies(node_tests table_node ${PROJECT_NAME}_generate_messages_cpp)
target_compile_definitions(node_tests PRIVATE CUE_SIM_TEST_DIR="${CMAKE_CURRENT_BINARY_DIR}")

add_rostest_gtest(research_tests test/node/research_interface.test test/node/test_research_interface.cpp test/node/rostest_main.cpp)
target_include_directories(research_tests PRIVATE ${catkin_INCLUDE_DIRS})
target_link_libraries(research_tests cue_sim_physics ${catkin_LIBRARIES})
add_dependencies(research_tests table_node ${PROJECT_NAME}_generate_messages_cpp)

add_rostest_gtest(followed_cue_tests test/node/followed_cue.test test/node/test_followed_cue.cpp test/node/rostest_main.cpp)
target_include_directories(followed_cue_tests PRIVATE ${catkin_INCLUDE_DIRS})
target_link_libraries(followed_cue_tests cue_sim_physics ${catkin_LIBRARIES})
add_dependencies(followed_cue_tests table_node ${PROJECT_NAME}_generate_messages_cpp)

# The example cue robot strikes through its tf as ~strike_cue would, at 100 Hz and 1 kHz of joint
# states (a 1 kHz Python controller and robot_state_publisher: alone, so as not to load the rest).
foreach(rate 100hz 1khz)
  add_rostest(test/node/robot_agreement_${rate}.test DEPENDENCIES table_node ${PROJECT_NAME}_generate_messages_py)
  set_tests_properties(_ctest_cue_sim_rostest_test_node_robot_agreement_${rate}.test PROPERTIES RUN_SERIAL TRUE)
endforeach()

add_rostest_gtest(sim_control_tests test/node/sim_control.test test/node/test_sim_control.cpp test/node/rostest_main.cpp)
target_include_directories(sim_control_tests PRIVATE ${catkin_INCLUDE_DIRS})
target_link_libraries(sim_control_tests cue_sim_table_description ${catkin_LIBRARIES})
add_dependencies(sim_control_tests table_node ${PROJECT_NAME}_generate_messages_cpp)
target_compile_definitions(sim_control_tests PRIVATE CUE_SIM_TEST_DIR="${CMAKE_CURRENT_BINARY_DIR}")

add_rostest_gtest(game_node_tests test/node/game.test test/node/test_game.cpp test/node/rostest_main.cpp)
target_include_directories(game_node_tests PRIVATE ${catkin_INCLUDE_DIRS})
target_link_libraries(game_node_tests cue_sim_table_description ${catkin_LIBRARIES})
add_dependencies(game_node_tests table_node ${PROJECT_NAME}_generate_messages_cpp)
target_compile_definitions(game_node_tests PRIVATE CUE_SIM_TEST_DIR="${CMAKE_CURRENT_BINARY_DIR}")
add_rostest(test/node/game_replay.test DEPENDENCIES game_node_tests self_play)
# Sim time as fast as possible keeps a core busy while balls move: alone. (The replays that waited out
# their 120 s for ~state, 2026-11-25 and 2026-11-29, lagged behind a node that published still frames
# as fast as it could at rest; at rest the clock now steps once a period.)
set_tests_properties(_ctest_cue_sim_rostest_test_node_game_replay.test PROPERTIES RUN_SERIAL TRUE)
add_rostest(test/node/game_replay_carom.test DEPENDENCIES game_node_tests self_play)
set_tests_properties(_ctest_cue_sim_rostest_test_node_game_replay_carom.test PROPERTIES RUN_SERIAL TRUE)
add_rostest(test/node/game_replay_snooker.test DEPENDENCIES game_node_tests self_play)
set_tests_properties(_ctest_cue_sim_rostest_test_node_game_replay_snooker.test PROPERTIES RUN_SERIAL TRUE)

# The same scenes through the Python module, the simulate program and the node's ~predict.
add_rostest(test/node/same_answers.test DEPENDENCIES table_node simulate cue_sim_python)
# Learning episodes played on the live node (cue_sim.envs.live).
add_rostest(test/node/live_env.test DEPENDENCIES table_node cue_sim_python)

# The simulated camera and the example detector (scripts/detect_balls.py) on it.
add_rostest(test/node/camera.test DEPENDENCIES table_node)
# The camera at 1920x1200 and 30 Hz and the detector take both cores: alone, not beside tests that
# record or time things.
set_tests_properties(_ctest_cue_sim_rostest_test_node_camera.test PROPERTIES RUN_SERIAL TRUE)

# A calibration session end to end: shots on the node, the camera, the detector, a bag, the fit, the fit
# loaded back (launch/calibration_record.launch, cue_sim.calibrate). The camera and the detector take both
# cores: alone.
add_rostest(test/node/calibration.test DEPENDENCIES table_node cue_sim_python)
set_tests_properties(_ctest_cue_sim_rostest_test_node_calibration.test PROPERTIES RUN_SERIAL TRUE)

# The table as a nodelet beside image_proc's rectify in one manager, and unloaded from it.
add_rostest_gtest(nodelet_tests test/node/nodelet.test test/node/test_nodelet.cpp test/node/rostest_main.cpp)
target_include_directories(nodelet_tests PRIVATE ${catkin_INCLUDE_DIRS})
target_link_libraries(nodelet_tests ${catkin_LIBRARIES})
add_dependencies(nodelet_tests cue_sim_nodelets ${PROJECT_NAME}_generate_messages_cpp)

add_rostest_gtest(examples_tests test/node/examples.test test/node/test_examples.cpp test/node/rostest_main.cpp)
target_include_directories(examples_tests PRIVATE ${catkin_INCLUDE_DIRS})
target_link_libraries(examples_tests ${catkin_LIBRARIES})
add_dependencies(examples_tests table_node plan_shots ${PROJECT_NAME}_generate_messages_cpp)
target_compile_definitions(examples_tests PRIVATE CUE_SIM_SOURCE_DIR="${PROJECT_SOURCE_DIR}")

add_rostest_gtest(node_load_tests test/node/node_load.test test/node/test_node_load.cpp test/node/rostest_main.cpp)
target_include_directories(node_load_tests PRIVATE ${catkin_INCLUDE_DIRS})
target_link_libraries(node_load_tests ${catkin_LIBRARIES})
add_dependencies(node_load_tests table_node ${PROJECT_NAME}_generate_messages_cpp)
# It measures tf's rate: alone on the machine, not beside another test's node.
set_tests_properties(_ctest_cue_sim_rostest_test_node_node_load.test PROPERTIES RUN_SERIAL TRUE)

# The folder arrows run one way: the physics core's models and table, engine, contacts, search and
# shots, and the package's layers around it (scripts/check_layers.py; doc/architecture.md).
catkin_run_tests_target("layers" "check_layers" "layers-check_layers.xml"
  COMMAND "/usr/bin/python3 ${PROJECT_SOURCE_DIR}/scripts/check_layers.py ${PROJECT_SOURCE_DIR} --junit ${CATKIN_TEST_RESULTS_DIR}/${PROJECT_NAME}/layers-check_layers.xml")

# The Python module (pytest, Debian's python3-pytest): test/python.
catkin_run_tests_target("pytest" "python" "pytest-python.xml"
  COMMAND "env CUE_SIM_SIMULATE=$<TARGET_FILE:simulate> /usr/bin/python3 -m pytest ${PROJECT_SOURCE_DIR}/test/python -q -p no:cacheprovider --junitxml=${CATKIN_TEST_RESULTS_DIR}/${PROJECT_NAME}/pytest-python.xml"
  DEPENDENCIES cue_sim_python simulate)
# The longest test (4 to 11 minutes): first, beside the others, not last and alone (ctest -j2 starts
# the costliest first; a fresh build has no timings of its own to rank them by).
set_tests_properties(_ctest_cue_sim_pytest_python PROPERTIES COST 1000)

# rviz without complaints: 60 s of rviz under Xvfb while a client racks, breaks, previews, steps,
# aims, strikes and starts games; fails on any error or warning rviz prints.
add_test(NAME rviz_quiet COMMAND ${PROJECT_SOURCE_DIR}/scripts/rviz_quiet.sh 60)
# rviz (software GL) and the camera it shows take both cores: alone, not beside tests that time things.
set_tests_properties(rviz_quiet PROPERTIES RUN_SERIAL TRUE TIMEOUT 300 ENVIRONMENT "CUE_SIM_BUILD=${CMAKE_BINARY_DIR};CUE_SIM_DEVEL=${CATKIN_DEVEL_PREFIX}")

catkin_add_gtest(learning_tests test/learning/test_environment.cpp)
target_link_libraries(learning_tests cue_sim_learning cue_sim_table_description gtest_main)
target_include_directories(learning_tests PRIVATE src)

catkin_add_gtest(calibration_tests test/calibration/test_track_prediction.cpp test/calibration/test_shot_film.cpp
  test/calibration/test_arrow_least_squares.cpp)
target_link_libraries(calibration_tests cue_sim_calibration cue_sim_least_squares cue_sim_table_description gtest_main)
target_include_directories(calibration_tests PRIVATE src)

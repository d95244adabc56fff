# The libraries without ROS: the physics core, games, tables from URDF and scene files, the live
# table, the simulated camera and the learning environments. Included by the catkin build
# (CMakeLists.txt) and by the Python-only build that `pip install .` runs (python/CMakeLists.txt),
# with CUE_SIM_ROOT the repository, and CUE_SIM_URDF_DIRS and CUE_SIM_CONFIG_DIRS where tables and
# calibrations are looked for at run time.

# The physics core: no ROS. Each contact model is one file in models/<kind> (ball_ball, cushion,
# ball_table, cue), named as include/cue_sim/physics/contact_models.def declares it.
file(GLOB CUE_SIM_CONTACT_MODELS CONFIGURE_DEPENDS ${CUE_SIM_ROOT}/src/physics/models/ball_ball/*.cpp
  ${CUE_SIM_ROOT}/src/physics/models/cushion/*.cpp ${CUE_SIM_ROOT}/src/physics/models/ball_table/*.cpp
  ${CUE_SIM_ROOT}/src/physics/models/cue/*.cpp)
add_library(cue_sim_physics
  # motion and collision models
  ${CUE_SIM_ROOT}/src/physics/models/event.cpp
  ${CUE_SIM_ROOT}/src/physics/models/motion.cpp
  ${CUE_SIM_ROOT}/src/physics/models/flight.cpp
  ${CUE_SIM_ROOT}/src/physics/models/orientation.cpp
  ${CUE_SIM_ROOT}/src/physics/models/physics_params.cpp
  ${CUE_SIM_ROOT}/src/physics/models/model_registry.cpp
  ${CUE_SIM_ROOT}/src/physics/models/frictional_impact.cpp
  ${CUE_SIM_CONTACT_MODELS}
  # tables and racks
  ${CUE_SIM_ROOT}/src/physics/table/table_model.cpp
  ${CUE_SIM_ROOT}/src/physics/table/table_closure.cpp
  ${CUE_SIM_ROOT}/src/physics/table/snooker_markings.cpp
  ${CUE_SIM_ROOT}/src/physics/table/rack.cpp
  # the engine: the immutable model, and the table's geometry as the search reads it
  ${CUE_SIM_ROOT}/src/physics/engine/engine.cpp
  ${CUE_SIM_ROOT}/src/physics/engine/table_geometry.cpp
  ${CUE_SIM_ROOT}/src/physics/engine/table_departure.cpp
  ${CUE_SIM_ROOT}/src/physics/engine/held_balls.cpp
  # balls in sustained contact: where they touch, the contact equations, their integration
  ${CUE_SIM_ROOT}/src/physics/supports/contact_geometry.cpp
  ${CUE_SIM_ROOT}/src/physics/supports/contact_system.cpp
  ${CUE_SIM_ROOT}/src/physics/supports/support_step.cpp
  # the event search: the simulation (and runs of one), its queue and grid, roots and contact
  # times, and the full scan it is checked against
  ${CUE_SIM_ROOT}/src/physics/search/simulation.cpp
  ${CUE_SIM_ROOT}/src/physics/search/event_search.cpp
  ${CUE_SIM_ROOT}/src/physics/search/candidates.cpp
  ${CUE_SIM_ROOT}/src/physics/search/airborne_walls.cpp
  ${CUE_SIM_ROOT}/src/physics/search/full_scan.cpp
  ${CUE_SIM_ROOT}/src/physics/search/polynomial.cpp
  # what an event does: impacts of touching groups, sustained contact, pocketing
  ${CUE_SIM_ROOT}/src/physics/contacts/event_resolution.cpp
  ${CUE_SIM_ROOT}/src/physics/contacts/impact_group.cpp
  ${CUE_SIM_ROOT}/src/physics/contacts/sustained_contact.cpp
  ${CUE_SIM_ROOT}/src/physics/contacts/support_groups.cpp
  # shots: aiming a cue, execution noise, batches on a thread pool
  ${CUE_SIM_ROOT}/src/physics/shots/cue_aim.cpp
  ${CUE_SIM_ROOT}/src/physics/shots/cue_sweep.cpp
  ${CUE_SIM_ROOT}/src/physics/shots/execution_noise.cpp
  ${CUE_SIM_ROOT}/src/physics/shots/batch.cpp
  ${CUE_SIM_ROOT}/src/physics/shots/thread_pool.cpp
)
target_include_directories(cue_sim_physics PUBLIC ${CUE_SIM_ROOT}/include PRIVATE ${CUE_SIM_ROOT}/src)
# Link-time optimisation across the core's sources: the event loop calls across files (search,
# candidates, contacts, motion) on every event.
include(CheckIPOSupported)
check_ipo_supported(RESULT CUE_SIM_IPO LANGUAGES CXX)
if(CUE_SIM_IPO)
  set_property(TARGET cue_sim_physics PROPERTY INTERPROCEDURAL_OPTIMIZATION TRUE)
endif()
find_package(Threads REQUIRED)
target_link_libraries(cue_sim_physics PUBLIC Eigen3::Eigen Threads::Threads)

# Games: rulesets, the referee and a game played on the engine. No ROS.
file(GLOB CUE_SIM_RULESETS CONFIGURE_DEPENDS ${CUE_SIM_ROOT}/src/game/rules/*.cpp)
add_library(cue_sim_game ${CUE_SIM_ROOT}/src/game/shot_facts.cpp ${CUE_SIM_ROOT}/src/game/referee.cpp
  ${CUE_SIM_ROOT}/src/game/game_play.cpp ${CUE_SIM_ROOT}/src/game/self_play.cpp
  ${CUE_SIM_RULESETS})
target_include_directories(cue_sim_game PUBLIC ${CUE_SIM_ROOT}/include PRIVATE ${CUE_SIM_ROOT}/src)
target_link_libraries(cue_sim_game PUBLIC cue_sim_physics)

# Tables from URDF (urdfdom) and scene files (yaml-cpp): no ROS either.
add_library(cue_sim_table_description
  ${CUE_SIM_ROOT}/src/table_description/urdf_table_loader.cpp
  ${CUE_SIM_ROOT}/src/table_description/table_catalog.cpp
  ${CUE_SIM_ROOT}/src/scene/scene_file.cpp
  ${CUE_SIM_ROOT}/src/scene/shot_report.cpp
  ${CUE_SIM_ROOT}/src/scene/game_record.cpp
  ${CUE_SIM_ROOT}/src/scene/ball_colours.cpp
)
target_include_directories(cue_sim_table_description PUBLIC ${CUE_SIM_ROOT}/include ${urdfdom_INCLUDE_DIRS})
target_link_libraries(cue_sim_table_description PUBLIC cue_sim_physics cue_sim_game ${urdfdom_LIBRARIES} ${console_bridge_LIBRARIES} yaml-cpp
  nlohmann_json::nlohmann_json)
target_compile_definitions(cue_sim_table_description PRIVATE CUE_SIM_URDF_DIRS="${CUE_SIM_URDF_DIRS}")

# The live table: what the node does with the table, without ROS.
add_library(cue_sim_session
  ${CUE_SIM_ROOT}/src/session/live_table.cpp
  ${CUE_SIM_ROOT}/src/session/live_table_edits.cpp
  ${CUE_SIM_ROOT}/src/session/table_clock.cpp
  ${CUE_SIM_ROOT}/src/session/live_balls.cpp
  ${CUE_SIM_ROOT}/src/session/ball_orientations.cpp
  ${CUE_SIM_ROOT}/src/session/table_edits.cpp
  ${CUE_SIM_ROOT}/src/session/live_game.cpp
  ${CUE_SIM_ROOT}/src/session/ball_input.cpp
  ${CUE_SIM_ROOT}/src/session/shot_prediction.cpp
  ${CUE_SIM_ROOT}/src/session/shot_preview.cpp
  ${CUE_SIM_ROOT}/src/session/cue_follower.cpp
)
target_link_libraries(cue_sim_session PUBLIC cue_sim_physics cue_sim_game)

# The simulated camera: renders the table and the balls through a calibrated lens (OpenCV for
# images and text, no ROS).
find_package(OpenCV REQUIRED COMPONENTS core imgproc)
add_library(cue_sim_camera
  ${CUE_SIM_ROOT}/src/camera/pinhole_camera.cpp
  ${CUE_SIM_ROOT}/src/camera/table_texture.cpp
  ${CUE_SIM_ROOT}/src/camera/ball_appearance.cpp
  ${CUE_SIM_ROOT}/src/camera/table_camera.cpp
  ${CUE_SIM_ROOT}/src/camera/exposure.cpp
  ${CUE_SIM_ROOT}/src/camera/calibration_file.cpp
)
target_include_directories(cue_sim_camera PUBLIC ${CUE_SIM_ROOT}/include ${OpenCV_INCLUDE_DIRS} PRIVATE ${CUE_SIM_ROOT}/src)
target_link_libraries(cue_sim_camera PUBLIC cue_sim_session cue_sim_table_description opencv_core opencv_imgproc)
# Where the default calibration is found without ROS: the source tree, then the install space.
target_compile_definitions(cue_sim_camera PRIVATE CUE_SIM_CONFIG_DIRS="${CUE_SIM_CONFIG_DIRS}")

# Learning environments: tasks played a shot a step, their actions and observations (the state,
# or the camera's pixels), and N tables stepped on every core. No ROS, no Python.
file(GLOB CUE_SIM_TASKS CONFIGURE_DEPENDS ${CUE_SIM_ROOT}/src/learning/tasks/*.cpp)
add_library(cue_sim_learning
  ${CUE_SIM_ROOT}/src/learning/environment.cpp
  ${CUE_SIM_ROOT}/src/learning/vector_environment.cpp
  ${CUE_SIM_ROOT}/src/learning/actions.cpp
  ${CUE_SIM_ROOT}/src/learning/state_observation.cpp
  ${CUE_SIM_ROOT}/src/learning/pixel_renderer.cpp
  ${CUE_SIM_TASKS}
)
target_include_directories(cue_sim_learning PUBLIC ${CUE_SIM_ROOT}/include PRIVATE ${CUE_SIM_ROOT}/src)
target_link_libraries(cue_sim_learning PUBLIC cue_sim_game cue_sim_camera)

# Calibration: where a shot's balls are at the instants they were observed, for fitting the
# simulator's coefficients to a real table (cue_sim.calibrate), and a shot filmed by the simulated
# camera (what the fit is proven on end to end). No ROS, no Python.
add_library(cue_sim_calibration ${CUE_SIM_ROOT}/src/calibration/track_prediction.cpp
  ${CUE_SIM_ROOT}/src/calibration/shot_film.cpp)
target_include_directories(cue_sim_calibration PUBLIC ${CUE_SIM_ROOT}/include PRIVATE ${CUE_SIM_ROOT}/src)
target_link_libraries(cue_sim_calibration PUBLIC cue_sim_physics cue_sim_camera)
# The fit's solver: robust least squares shaped like an arrow (the coefficients shared by every shot,
# each shot's unknowns its own), by Ceres with each shot's unknowns eliminated by its Schur
# complement. Its own library: only the Python module's fit needs Ceres.
find_package(Ceres REQUIRED)
add_library(cue_sim_least_squares ${CUE_SIM_ROOT}/src/calibration/arrow_least_squares.cpp)
target_include_directories(cue_sim_least_squares PUBLIC ${CUE_SIM_ROOT}/include)
target_link_libraries(cue_sim_least_squares PRIVATE Ceres::ceres)

# The soak campaign: random scenes on the bundled tables, each checked at every event. No ROS; the
# `soak` program and the Python module (cue_sim.soak, its shards on Dask) run it.
add_library(cue_sim_soak ${CUE_SIM_ROOT}/src/evaluation/soak/soak_scenes.cpp
  ${CUE_SIM_ROOT}/src/evaluation/soak/soak_checks.cpp ${CUE_SIM_ROOT}/src/evaluation/soak/soak_campaign.cpp
  ${CUE_SIM_ROOT}/src/evaluation/soak/shot_ending.cpp)
target_include_directories(cue_sim_soak PUBLIC ${CUE_SIM_ROOT}/include PRIVATE ${CUE_SIM_ROOT}/src)
target_link_libraries(cue_sim_soak PUBLIC cue_sim_table_description)

# The Python module cue_sim._core's sources and libraries, for both builds to make it from.
set(CUE_SIM_PYTHON_SOURCES ${CUE_SIM_ROOT}/src/python/module.cpp ${CUE_SIM_ROOT}/src/python/state_arrays.cpp
  ${CUE_SIM_ROOT}/src/python/game_bindings.cpp ${CUE_SIM_ROOT}/src/python/learning_bindings.cpp
  ${CUE_SIM_ROOT}/src/python/calibration_bindings.cpp ${CUE_SIM_ROOT}/src/python/least_squares_bindings.cpp
  ${CUE_SIM_ROOT}/src/python/soak_bindings.cpp)
set(CUE_SIM_PYTHON_LIBRARIES cue_sim_session cue_sim_table_description cue_sim_learning cue_sim_calibration
  cue_sim_least_squares cue_sim_soak)

# Quilting stages: seed finding, element correspondences, element deformation. The stage sources
# are compiled into their tests directly so each test builds even while other parts of
# meshquilt_quilt are in progress.
set(stage_dir ${PROJECT_SOURCE_DIR}/host/quilt)
meshquilt_test(seed_finding_test
  SOURCES seed_finding_test.cpp ${stage_dir}/seed_finding.cpp
  LIBS meshquilt_mesh meshquilt_engine)
meshquilt_test(element_deformation_test
  SOURCES element_deformation_test.cpp ${stage_dir}/element_deformation.cpp
  LIBS meshquilt_mesh meshquilt_engine Eigen3::Eigen)
meshquilt_test(correspondence_test
  SOURCES correspondence_test.cpp ${stage_dir}/correspondence.cpp
  LIBS meshquilt_spatial meshquilt_mesh meshquilt_engine)

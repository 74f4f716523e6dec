# Element merging: graph cut, stitching, merge_elements. Sources are compiled into the tests so
# they build while other parts of meshquilt_quilt are in progress.
set(merging_dir ${PROJECT_SOURCE_DIR}/host/quilt)
meshquilt_test(graph_cut_test
  SOURCES graph_cut_test.cpp ${merging_dir}/graph_cut.cpp
  LIBS meshquilt_mesh Boost::boost)
meshquilt_test(stitching_test
  SOURCES stitching_test.cpp ${merging_dir}/stitching.cpp ${merging_dir}/element_deformation.cpp
  LIBS meshquilt_mesh Eigen3::Eigen)
meshquilt_test(element_merging_test
  SOURCES element_merging_test.cpp ${merging_dir}/element_merging.cpp ${merging_dir}/graph_cut.cpp
          ${merging_dir}/stitching.cpp ${merging_dir}/element_deformation.cpp
  LIBS meshquilt_spatial meshquilt_mesh Eigen3::Eigen Boost::boost)

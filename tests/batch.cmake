# meshquilt batch: manifests, shards, resumable records, the report; and a real Slurm array job.
meshquilt_test(batch_test NEEDS_CLI SOURCES batch_test.cpp LABELS end_to_end)
add_test(NAME batch_slurm_test
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/batch_slurm_test.sh $<TARGET_FILE:meshquilt> ${PROJECT_SOURCE_DIR})
set_tests_properties(batch_slurm_test PROPERTIES LABELS "slurm;end_to_end" SKIP_RETURN_CODE 77 TIMEOUT 300)

// advect_dir_branches: its test is in pdv_predict_branches_test.cpp (one file
// for the two kernels of issue 20's defect 4).

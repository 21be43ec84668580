# schedule.sh: the workgroup of a GPU kernel, read from its banner (sourced by the tests and the
# benchmarks that dispatch kernels).

# kernel_schedule KERNEL: prints "PQ Q", the threads and the patches of a workgroup, from the
# kernel's "Schedule: P threads per patch, Q patches per workgroup (PQ threads)" line (either form;
# OpenCL's --kernel lanes: "N patches per thread (floatN vectors), Q patches ... (Q/N threads)").
kernel_schedule() {
    sed -n 's/^ \* Schedule: [0-9]* \(threads\{0,1\} per patch\|patches per thread (float[0-9]* vectors)\), \([0-9]*\) patches per workgroup (\([0-9]*\) threads).*/\3 \2/p' "$1"
}

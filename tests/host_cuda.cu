/* host_cuda.cu: runs an emitted CUDA kernel (--target cuda) over patch sets and checks it with kref.
 * Built per kernel: nvcc -DKERNEL_FILE='"k.cu"' -DKERNEL=ptp_3x3_classify ... runs where a GPU is;
 * g++ -x c++ -DCUDA_EMU ... runs it on the CPU through tests/cuda_emu.h, bit for bit. */
extern "C" {
#include "check.h"
#include "kref.h"
}
#ifdef CUDA_EMU
#include "cuda_emu.h"
/* The one seam: a launch is a call to the emulation, or the language's. */
#define LAUNCH(kernel, grid, block, ...) cuda_emu_launch(grid, block, [&] { kernel(__VA_ARGS__); })
#else
#include <cuda_runtime.h>
#define LAUNCH(kernel, grid, block, ...) kernel<<<grid, block>>>(__VA_ARGS__)
#endif
#include KERNEL_FILE

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The command line and the comparisons over all sets. */
typedef struct {
    const kref_args *o;
    kref_result res;
} run;

/* Runs the kernel over one set (ctx: a run); 0 on success, else a "not ok" line was printed. */
static int run_set(void *ctx, const kref_ref *ref, const kref_set *s)
{
    const kref_args *o = ((run *)ctx)->o;
    kref_result *res = &((run *)ctx)->res;
    size_t K = (size_t)ref->K, L = (size_t)ref->L, groups = (s->count + o->q - 1) / o->q;
    size_t gx = groups < 65535 ? groups : 65535, gy = (groups + gx - 1) / gx;
    unsigned *cls = (unsigned *)malloc(s->count * sizeof *cls);
    float *planes = (float *)malloc(s->count * L * sizeof *planes);
    float4 *d_cp = NULL, eye = make_float4(s->eye[0], s->eye[1], s->eye[2], s->eye[3]);
    unsigned *d_cls = NULL;
    float *d_planes = NULL;
    cudaError_t e;
    int ok = 0;
    if (!cls || !planes)
        goto done;
    if ((e = cudaMalloc(&d_cp, s->count * K * sizeof *d_cp)) != cudaSuccess ||
        (e = cudaMalloc(&d_cls, s->count * sizeof *d_cls)) != cudaSuccess ||
        (o->planes && (e = cudaMalloc(&d_planes, s->count * L * sizeof *d_planes)) != cudaSuccess) ||
        (e = cudaMemcpy(d_cp, s->cp, s->count * K * sizeof *d_cp, cudaMemcpyHostToDevice)) != cudaSuccess ||
        (e = cudaMemset(d_cls, 0xFF, s->count * sizeof *d_cls)) != cudaSuccess) {
        check(0, o->label, "%s: %s", s->name, cudaGetErrorString(e));
        goto done;
    }
    LAUNCH(KERNEL, dim3((unsigned)gx, (unsigned)gy), dim3((unsigned)o->pq), d_cp, d_cls, d_planes, eye,
           (unsigned)s->count);
    if ((e = cudaDeviceSynchronize()) != cudaSuccess || (e = cudaGetLastError()) != cudaSuccess ||
        (e = cudaMemcpy(cls, d_cls, s->count * sizeof *cls, cudaMemcpyDeviceToHost)) != cudaSuccess ||
        (o->planes &&
         (e = cudaMemcpy(planes, d_planes, s->count * L * sizeof *planes, cudaMemcpyDeviceToHost)) !=
             cudaSuccess)) {
        check(0, o->label, "%s: %s", s->name, cudaGetErrorString(e));
        goto done;
    }
    kref_check(res, ref, s, cls, o->planes ? planes : NULL);
    ok = 1;
done:
    cudaFree(d_cp);
    cudaFree(d_cls);
    cudaFree(d_planes);
    free(cls);
    free(planes);
    return !ok;
}

int main(int argc, char **argv)
{
    kref_args o;
    kref_ref ref;
    run r;
    int ndev = 0, failed;
    if (kref_parse_args(&o, argc, argv, "host_cuda", KREF_NEED_BLOCK))
        return 2;
    if (cudaGetDeviceCount(&ndev) != cudaSuccess || ndev == 0) {
        printf("# %s: no CUDA device here: built, not run\n", o.label);
        return 0;
    }
#ifdef CUDA_EMU
    printf("# %s: emulated on the CPU (tests/cuda_emu.h)\n", o.label);
#endif
    if (kref_init_args(&ref, &o))
        return 1;
    memset(&r, 0, sizeof r);
    r.o = &o;
    failed = kref_each_set(&ref, &o, run_set, &r, NULL) != 0;
    if (!failed)
        failed = !kref_report(&r.res, o.label);
    kref_clear(&ref);
    return failed || check_exit();
}

/* cuda_emu.h: runs an emitted CUDA kernel on the CPU, compiled as C++ by g++ or clang++, with the
 * runtime calls tests/host_cuda.cu makes; included before the kernel when CUDA_EMU is defined.
 *
 * Contract. Build with -ffp-contract=off and without -ffast-math. The kernels spell every
 * rounding: __fmul_rn is a*b, __fsub_rn a-b, __fmaf_rn fmaf (one rounding), and their other adds,
 * subtracts and products are binary32 round to nearest, unfused; denormals are kept (no
 * -ffast-math, no flush to zero). The emulation computes exactly those operations in that order: it is bit for bit
 * what nvcc builds. nvcc's default (-fmad=true) would fuse a plain product with the add it feeds,
 * but the kernels write every float product with __fmul_rn, which it never fuses (test_kernels.sh
 * checks that the PTX equals that of -fmad=false).
 * A launch runs the blocks one after another (so __shared__, which is static here, is one block's
 * memory), and a block's threads as coroutines: each runs until its next __syncthreads() or its
 * end, then the next thread runs; threadIdx is the running thread's. Even blocks run their threads
 * in order 0..n-1, odd blocks in reverse, so that a missing barrier shows in some block whichever
 * thread reads first. A barrier that some threads reach while others have returned aborts.
 * What it proves: the kernel's logic (indexing, barriers, shared memory use between barriers,
 * bounds, second look) and every rounding the source spells. What it does not: nvcc's code
 * generation (the nvcc compile tests cover it), warp-level scheduling beyond the barrier
 * semantics, races between threads within one barrier interval (here they run one at a time). */
#ifndef CUDA_EMU_H
#define CUDA_EMU_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#if defined(__FAST_MATH__)
#error "cuda_emu.h: build without -ffast-math (it would change the kernels' roundings)"
#endif

#define __global__
#define __device__
#define __constant__
#define __shared__ static
#define __launch_bounds__(n)
#define __syncthreads() cuda_emu_sync()

struct float2 { float x, y; };
struct float4 { float x, y, z, w; };
struct uint3 { unsigned x, y, z; };
struct dim3 {
    unsigned x, y, z;
    dim3(unsigned a = 1, unsigned b = 1, unsigned c = 1) : x(a), y(b), z(c) {}
};
static inline float2 make_float2(float x, float y) { float2 v = {x, y}; return v; }
static inline float4 make_float4(float x, float y, float z, float w) { float4 v = {x, y, z, w}; return v; }
static inline float __fmul_rn(float a, float b) { return a * b; }
static inline float __fsub_rn(float a, float b) { return a - b; }
static inline float __fmaf_rn(float a, float b, float c) { return fmaf(a, b, c); }
static inline unsigned __float_as_uint(float f)
{
    unsigned u;
    memcpy(&u, &f, sizeof u);
    return u;
}

/* The running thread's indices, and the launch's. */
static uint3 threadIdx, blockIdx;
static dim3 gridDim, blockDim;

/* The runtime calls of the host: device memory is host memory. */
typedef enum { cudaSuccess = 0, cudaErrorMemoryAllocation = 2 } cudaError_t;
enum cudaMemcpyKind { cudaMemcpyHostToDevice = 1, cudaMemcpyDeviceToHost = 2 };
template <class T> static cudaError_t cudaMalloc(T **p, size_t bytes)
{
    *p = (T *)malloc(bytes ? bytes : 1);
    return *p ? cudaSuccess : cudaErrorMemoryAllocation;
}
static inline cudaError_t cudaFree(void *p) { free(p); return cudaSuccess; }
static inline cudaError_t cudaMemcpy(void *d, const void *s, size_t n, cudaMemcpyKind)
{
    memcpy(d, s, n);
    return cudaSuccess;
}
static inline cudaError_t cudaMemset(void *d, int v, size_t n) { memset(d, v, n); return cudaSuccess; }
static inline cudaError_t cudaDeviceSynchronize(void) { return cudaSuccess; }
static inline cudaError_t cudaGetLastError(void) { return cudaSuccess; }
static inline cudaError_t cudaGetDeviceCount(int *n) { *n = 1; return cudaSuccess; }
static inline const char *cudaGetErrorString(cudaError_t e) { return e ? "out of memory" : "no error"; }

/* The coroutines: a saved stack pointer per thread. On x86-64 a switch saves the callee-saved
 * registers on the stack and swaps stack pointers (a few ns); elsewhere ucontext (a system call a
 * switch, about 7 times slower here; -DCUDA_EMU_UCONTEXT picks it on x86-64 too, e.g. where a
 * CET shadow stack refuses the switch's ret into a new stack). */
enum { CUDA_EMU_STACK = 256 * 1024 };
#if defined(__x86_64__) && defined(__linux__) && !defined(CUDA_EMU_UCONTEXT)
extern "C" void cuda_emu_swap(void **save, void *next);
__asm__(".text\n.globl cuda_emu_swap\n.type cuda_emu_swap,@function\ncuda_emu_swap:\n"
        "pushq %rbp\npushq %rbx\npushq %r12\npushq %r13\npushq %r14\npushq %r15\n"
        "movq %rsp, (%rdi)\nmovq %rsi, %rsp\n"
        "popq %r15\npopq %r14\npopq %r13\npopq %r12\npopq %rbx\npopq %rbp\nret\n"
        ".size cuda_emu_swap, .-cuda_emu_swap\n");
typedef void *cuda_emu_ctx;
/* A context that starts entry() on the stack that ends at top. */
static void cuda_emu_make(cuda_emu_ctx *c, char *top, void (*entry)(void))
{
    void **sp = (void **)((size_t)top & ~(size_t)15) - 8; /* 6 registers, entry, a return slot */
    memset(sp, 0, 8 * sizeof *sp);
    sp[6] = (void *)entry;
    *c = sp;
}
static void cuda_emu_switch(cuda_emu_ctx *from, cuda_emu_ctx *to) { cuda_emu_swap(from, *to); }
#else
#include <ucontext.h>
typedef ucontext_t cuda_emu_ctx;
static void cuda_emu_make(cuda_emu_ctx *c, char *top, void (*entry)(void))
{
    getcontext(c);
    c->uc_stack.ss_sp = top - CUDA_EMU_STACK;
    c->uc_stack.ss_size = CUDA_EMU_STACK;
    c->uc_link = NULL;
    makecontext(c, entry, 0);
}
static void cuda_emu_switch(cuda_emu_ctx *from, cuda_emu_ctx *to) { swapcontext(from, to); }
#endif

/* The scheduler's state: the block's threads, the running one, the kernel call. */
static struct {
    cuda_emu_ctx sched, *ctx;
    char *stacks;
    unsigned char *done;
    unsigned n, cap, cur;
    void (*call)(void *);
    void *arg;
} cuda_emu;

/* A thread's body: the kernel, then back to the scheduler for good. */
static void cuda_emu_entry(void)
{
    cuda_emu.call(cuda_emu.arg);
    cuda_emu.done[cuda_emu.cur] = 1;
    cuda_emu_switch(&cuda_emu.ctx[cuda_emu.cur], &cuda_emu.sched);
    abort(); /* a finished thread is never resumed */
}

/* __syncthreads(): the running thread waits until every thread of the block has run to here. */
static inline void cuda_emu_sync(void)
{
    cuda_emu_switch(&cuda_emu.ctx[cuda_emu.cur], &cuda_emu.sched);
}

/* Room for blocks of n threads; 0, or -1 when memory runs out. */
static int cuda_emu_reserve(unsigned n)
{
    if (n <= cuda_emu.cap)
        return 0;
    free(cuda_emu.stacks);
    free(cuda_emu.ctx);
    free(cuda_emu.done);
    cuda_emu.stacks = (char *)malloc((size_t)n * CUDA_EMU_STACK);
    cuda_emu.ctx = (cuda_emu_ctx *)malloc(n * sizeof *cuda_emu.ctx);
    cuda_emu.done = (unsigned char *)malloc(n);
    cuda_emu.cap = cuda_emu.stacks && cuda_emu.ctx && cuda_emu.done ? n : 0;
    return cuda_emu.cap ? 0 : -1;
}

/* Runs block blockIdx: rounds of every unfinished thread (in order, or reversed) until all have
 * returned; aborts when a barrier is reached by some threads and not by others. */
static void cuda_emu_block(int reversed)
{
    unsigned i, k, left = cuda_emu.n, ran;
    memset(cuda_emu.done, 0, cuda_emu.n);
    for (i = 0; i < cuda_emu.n; i++)
        cuda_emu_make(&cuda_emu.ctx[i], cuda_emu.stacks + (size_t)(i + 1) * CUDA_EMU_STACK, cuda_emu_entry);
    while (left) {
        for (k = ran = 0; k < cuda_emu.n; k++) {
            i = reversed ? cuda_emu.n - 1 - k : k;
            if (cuda_emu.done[i])
                continue;
            cuda_emu.cur = i;
            threadIdx.x = i % blockDim.x;
            threadIdx.y = i / blockDim.x % blockDim.y;
            threadIdx.z = i / (blockDim.x * blockDim.y);
            cuda_emu_switch(&cuda_emu.sched, &cuda_emu.ctx[i]);
            ran++;
            left -= cuda_emu.done[i];
        }
        if (left && left != ran) {
            fprintf(stderr, "cuda_emu: __syncthreads() reached by %u threads of %u\n", left, ran);
            abort();
        }
    }
}

/* kernel<<<grid, block>>>: runs f() (the kernel call) on every thread of every block. */
template <class F> static cudaError_t cuda_emu_launch(dim3 grid, dim3 block, F f)
{
    unsigned x, y, z;
    if (cuda_emu_reserve(block.x * block.y * block.z))
        return cudaErrorMemoryAllocation;
    cuda_emu.n = block.x * block.y * block.z;
    cuda_emu.call = [](void *p) { (*(F *)p)(); };
    cuda_emu.arg = &f;
    gridDim = grid;
    blockDim = block;
    for (z = 0; z < grid.z; z++)
        for (y = 0; y < grid.y; y++)
            for (x = 0; x < grid.x; x++) {
                blockIdx.x = x, blockIdx.y = y, blockIdx.z = z;
                cuda_emu_block((x + y + z) & 1);
            }
    return cudaSuccess;
}

#endif

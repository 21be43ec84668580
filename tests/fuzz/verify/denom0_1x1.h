#define T_DENOM 0
#define T_THREADS 0
static const unsigned short t_idx[4][4] = {{0, 0, 1, 2}, {1, 0, 1, 3}, {2, 0, 2, 3}, {3, 1, 2, 3}};
static const float t_wgt[4] = {-1.0f, -1.0f, 1.0f, 1.0f};
static const int t_iwgt[4] = {-1, -1, 1, 99999999999999999999999999999999999999999};
static const unsigned short t_owner[3] = {0, 1, 2};
static const unsigned short t_sched_idx[5][4] = {{0, 0, 1, 2}, {1, 0, 1, 3}, {2, 0, 2, 3},
    {3, 1, 2, 3}, {0, 0, 1, 2}};
static const float t_sched_wgt[5] = {-1.0f, -1.0f, 1.0f, 1.0f, -1.0f};
static const int t_sched_iwgt[4] = {-1, -1, 1, 1};

// negated, scaled by 2: the opposite orientation
static const unsigned short my_1x1_idx[4][4] = {{0, 0, 1, 2}, {1, 0, 1, 3}, {2, 0, 2, 3}, {3, 1, 2, 3}};
static const float my_1x1_wgt[4] = {2.0f, 0x2, -2e0f, -2.f};

/* an idx name with many leading zeros in its degree */
static const unsigned short ptp_00000000000000000003x3_idx[1][4] = {{0, 0, 1, 2}};
static const float ptp_00000000000000000003x3_wgt[1] = {-1.0f};

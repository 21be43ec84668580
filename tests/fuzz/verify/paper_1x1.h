/* the paper's layout: rows {plane, j, k, l}, weights as fractions */
#include <stdint.h>
uint idx[4][] = {{3, 1, 2, 3}, {0, 0, 2, 1}, // order flipped
                 {2, 0, 2, 3}, {1, 0, 1, 3}};
#define W(x) (x)
float wgt[] = {1.0f, (float)(1/1), 2.0/2, -1e0f};

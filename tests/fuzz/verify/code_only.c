/* straight-line code */
unsigned classify(const float b[][4], const float e[4])
{
    float t = -(b[0][0] * e[2]);
    return t < 0;
}

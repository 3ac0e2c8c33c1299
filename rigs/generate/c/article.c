/* The S-curve article's table function, as the article gives it (written
 * out with its declarations): single precision, expf, a double-precision
 * reciprocal and a double-precision division by the 10 MHz timer's rate,
 * truncated to unsigned short. build.rs compiles it twice, the second time
 * with -ffp-contract=off and the name CalculateSModelLine_nocontract. */
#include <math.h>

void CalculateSModelLine(float fre[], unsigned short period[], float len, float fre_max, float fre_min, float flexible)
{
    int i;
    float deno;
    float melo;
    float delt = fre_max - fre_min;
    for (i = 0; i < len; i++) {
        melo = flexible * (i - len / 2) / (len / 2);
        deno = 1.0 / (1 + expf(-melo));
        fre[i] = delt * deno + fre_min;
        period[i] = (unsigned short)(10000000.0 / fre[i]);
    }
}

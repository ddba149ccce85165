/* Reports the device's view of the shared structs (kernels/shared/clr_types.h), so a test
 * can check that host and device agree byte for byte. One work-item writes
 * out[0..5] = sizes of ClrCamera, ClrSphere, ClrBillboard, ClrRay, ClrHit, ClrSceneInfo and
 * out[6..] = offsets of selected fields, in the order the test lists them. */
#ifndef CLR_LAYOUT_CL
#define CLR_LAYOUT_CL

#include "shared/clr_types.h"

#define CLR_OFFSET(type, field) ((int)((size_t) & (((type*)0)->field)))

__kernel void struct_layout(__global int* out)
{
    if (get_global_id(0) != 0)
        return;
    out[0] = sizeof(ClrCamera);
    out[1] = sizeof(ClrSphere);
    out[2] = sizeof(ClrBillboard);
    out[3] = sizeof(ClrRay);
    out[4] = sizeof(ClrHit);
    out[5] = sizeof(ClrSceneInfo);
    out[6] = CLR_OFFSET(ClrCamera, width);
    out[7] = CLR_OFFSET(ClrSphere, flags);
    out[8] = CLR_OFFSET(ClrBillboard, color);
    out[9] = CLR_OFFSET(ClrBillboard, texel_offset);
    out[10] = CLR_OFFSET(ClrBillboard, flags);
    out[11] = CLR_OFFSET(ClrHit, index);
    out[12] = CLR_OFFSET(ClrSceneInfo, sphere_count);
    out[13] = CLR_OFFSET(ClrSceneInfo, max_depth);
}

#endif /* CLR_LAYOUT_CL */

/* Reports the device's view of the shared structs (kernels/shared/clr_types.h), so a test
 * can check that host and device agree byte for byte. One work-item writes, for each entry of
 * CLR_LAYOUT_LIST (kernels/shared/clr_layout.h) in its order: a struct's size; a field's
 * offset, then its size. The host test expands the same list the same way. */
#ifndef CLR_LAYOUT_CL
#define CLR_LAYOUT_CL

#include "shared/clr_types.h"
#include "shared/clr_layout.h"

#define CLR_OFFSET(type, field) ((int)((size_t) & (((type*)0)->field)))

__kernel void struct_layout(__global int* out)
{
    if (get_global_id(0) != 0)
        return;
    int n = 0;
#define CLR_LAYOUT_STRUCT(type) out[n++] = (int)sizeof(type);
#define CLR_LAYOUT_FIELD(type, field)      \
    out[n++] = CLR_OFFSET(type, field);     \
    out[n++] = (int)sizeof(((type*)0)->field);
    CLR_LAYOUT_LIST
#undef CLR_LAYOUT_STRUCT
#undef CLR_LAYOUT_FIELD
}

#endif /* CLR_LAYOUT_CL */

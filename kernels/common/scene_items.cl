/* A scene item, as screen-tile lists and BVH leaves store it: the object's kind above its
 * index among the objects of that kind (CLR_ITEM_KIND_BITS, shared/clr_types.h). */
#ifndef CLR_COMMON_SCENE_ITEMS_CL
#define CLR_COMMON_SCENE_ITEMS_CL

#include "shared/clr_types.h"

/* The kind of object the item names: CLR_HIT_SPHERE, CLR_HIT_BILLBOARD, ... */
int item_kind(uint item)
{
    return (int)(item >> CLR_ITEM_INDEX_BITS);
}

/* The object's index among the objects of its kind. */
int item_index(uint item)
{
    return (int)(item & CLR_ITEM_INDEX_MASK);
}

#endif /* CLR_COMMON_SCENE_ITEMS_CL */

/* A scene item, as screen-tile lists and BVH leaves store it: an object index, with
 * CLR_TILE_BILLBOARD set for billboards (shared/clr_types.h). */
#ifndef CLR_COMMON_SCENE_ITEMS_CL
#define CLR_COMMON_SCENE_ITEMS_CL

#include "shared/clr_types.h"

/* CLR_HIT_SPHERE or CLR_HIT_BILLBOARD: the kind of object the item names. */
int item_kind(uint item)
{
    return (item & CLR_TILE_BILLBOARD) ? CLR_HIT_BILLBOARD : CLR_HIT_SPHERE;
}

/* The object's index among the spheres or among the billboards. */
int item_index(uint item)
{
    return (int)(item & ~CLR_TILE_BILLBOARD);
}

#endif /* CLR_COMMON_SCENE_ITEMS_CL */

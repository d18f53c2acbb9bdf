/* scene.h: the chain as a picture: the left wall, zig-zag springs, the masses to scale,
 * the piston and motor housing, drawn where the layout puts the scene. */
#ifndef SPRINGSIM_SCENE_H
#define SPRINGSIM_SCENE_H

#include "../app/app.h"
#include "../chart/layout.h"
#include "../app/select.h"

struct scene {
    struct canvas *canvas; /* the springs' dots */
};

/* Sizes the scene's canvas for layout l; false on no memory. */
bool scene_place(struct scene *s, const struct layout *l);

/* Frees the canvas. */
void scene_free(struct scene *s);

/* Draws the chain of app as it is now, with the selection sel highlighted. */
void scene_draw(struct scene *s, const struct layout *l, const struct app *app,
                const struct selection *sel);

#endif

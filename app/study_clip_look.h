#pragma once
// How the user study's clips show the cloth. Textured, each fabric has the colour of the sample
// it was measured on (Wang 2011's names: 11 oz black denim, gray interlock, royal blue pants
// fabric, white swimsuit) woven as a plain weave; hidden, every fabric is the same flat neutral
// colour with no threads at all, lit the same way, so only the motion and the tears tell the
// fabrics apart (thesis §3.4: "cloth textures are disabled"). A tear shows as the hole it opens:
// the renderer's red torn-edge lines (a debugging aid) are left out of both.
#include "render_view.h"
#include "study/fabric.h"

namespace weft::app {

void dressForStudy(ui::RenderView& view, study::Fabric fabric, bool textured);

}  // namespace weft::app

// The scene's blocks for what is in the world besides the sea (the floor, placed glTF objects, point
// lights) and the "render" block; scene.cpp composes them into the document.
#pragma once
#include "scene/json_fields.h"
#include "scene/scene.h"

namespace lagoon::scene {

void read_seafloor(ObjectReader& r, Seafloor& f);
void read_object(ObjectReader& r, Object& o);    // one element of "objects"
void read_vehicle(ObjectReader& r, Vehicle& v);  // one element of "vehicles"
void read_wakes(ObjectReader& r, Wakes& w);
void read_sediment(ObjectReader& r, Sediment& s);
void read_light(ObjectReader& r, PointLight& l);  // one element of "lights"
void read_render(ObjectReader& r, RenderSettings& s);
void read_underwater(ObjectReader& r, Underwater& u);

}  // namespace lagoon::scene

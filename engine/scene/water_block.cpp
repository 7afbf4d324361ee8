#include "scene/water_block.h"

#include <string>
#include <utility>
#include <vector>

#include "optics/water_types.h"

namespace lagoon::scene {

void read_water(ObjectReader& r, optics::WaterParams& w) {
  std::vector<std::pair<std::string, std::string>> types;
  for (const std::string& name : optics::water_type_names()) types.emplace_back(name, name);
  types.emplace_back("custom", "custom");
  r.choice("type", w.type, types,
           "Water type: a Jerlov type (I, IA, IB, II, III clear to turbid ocean; 1C-9C coastal, increasingly "
           "turbid) or \"custom\" with a table of your own.");
  r.text("table", w.table,
         "For type \"custom\": CSV file with columns wavelength_nm, absorption_per_m, scattering_per_m "
         "covering 380-780 nm; relative to the scene file's folder.");
  r.number("bottom_albedo", w.bottom_albedo, Bounds::between(0, 1), "",
           "Average bottom reflectance R̂ (diffuse); used for the water colour T1. The bottom texture "
           "itself tints T0.");
  r.choice(
      "phase", w.phase,
      std::vector<std::pair<std::string, std::string>>{{"mixed", "mixed"}, {"constant", "constant"}},
      "Scattering phase function: \"mixed\" = per wavelength, the mix of pure water (isotropic-like) and "
      "ocean particles (Petzold, g = 0.924) by their share of scattering; \"constant\" = phase_x1.");
  r.number(
      "phase_x1", w.phase_x1, Bounds::between(0, 2.99), "",
      "With phase \"constant\": first Legendre coefficient X1 of the phase function (3g for asymmetry g); "
      "0 = isotropic. Above 1 the model uses a similar phase function (docs/optics.md).");
  r.number(
      "diffuse_path_factor", w.diffuse_path_factor, Bounds::between(1, 4), "",
      "Path length of the diffuse light per metre of depth (1 / its mean cosine) in the four-flow model: "
      "2 = isotropic diffuse light, the default: K_d within 15 % of Jerlov's measurements for seven of the "
      "ten types; 1 = the seed's eq. 4 as printed (turbid water then attenuates 20-50 % too little) "
      "(docs/optics.md).");
  r.number("lut_gamma", w.lut_gamma, Bounds::between(0.05, 20), "",
           "Exponent γ of eq. 23: larger values keep the bottom visible deeper before the water colour "
           "takes over.");
  r.number("ior", w.ior, Bounds::between(1.0, 2.0), "", "Index of refraction of the water.");
  r.integer("lut_size", w.lut_size, Bounds::between(2, 512), "",
            "Samples of the colour LUTs along r and along h.");
  r.number("lut_r_max_m", w.lut_r_max_m, Bounds::above_up_to(0, 10000), "m",
           "Largest horizontal distance r of the LUTs (the refracted view ray's horizontal travel).");
  r.number("lut_h_max_m", w.lut_h_max_m, Bounds::above_up_to(0, 1000), "m",
           "Largest bottom depth h of the LUTs; deeper water takes the deep-water colour.");
  r.rule("table", w.type != "custom" || !w.table.empty(), "a file name when type is \"custom\"",
         "type \"custom\" reads the water's absorption and scattering from `table`; give its path");
}

}  // namespace lagoon::scene

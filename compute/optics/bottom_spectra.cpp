#include "optics/bottom_spectra.h"

#include "optics/csv_table.h"

namespace lagoon::optics {

const std::vector<BottomSpectrum>& bottom_spectra() {
  static const std::vector<BottomSpectrum> spectra = [] {
    const CsvTable table = embedded_table_or_abort("bottom_reflectance_5nm.csv");
    const std::pair<const char*, const char*> columns[] = {
        {"sand", "reef sand, in water (Asner lab via Koenig et al. 2023, mean of 24)"},
        {"coral", "live (brown) coral, in water (Asner lab via Koenig et al. 2023, mean of 101)"},
        {"coralline_algae",
         "red crustose coralline algae, in water (Asner lab via Koenig et al. 2023, mean of 751)"},
        {"macroalgae",
         "fleshy green-brown macroalgae, in water (Asner lab via Koenig et al. 2023, mean of 102)"},
        {"basalt", "grey terrestrial basalt, laboratory (RELAB c1bf01)"}};
    std::vector<BottomSpectrum> out;
    for (const auto& [name, description] : columns)
      out.push_back({name, description, grid_column_or_abort(table, name)});
    return out;
  }();
  return spectra;
}

}  // namespace lagoon::optics

#include "optics/water_types.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <optional>

#include "optics/csv_table.h"

namespace lagoon::optics {
namespace {

constexpr double kJerlovLastNm = 700.0;        // last published Jerlov wavelength
constexpr double kNonWaterSlopePerNm = 0.014;  // CDOM-like exponential slope beyond 700 nm

// y(at) by linear interpolation in a table with increasing x; `at` within [x.front(), x.back()].
double interpolate(const std::vector<double>& x, const std::vector<double>& y, double at) {
  const auto hi = std::upper_bound(x.begin(), x.end(), at);
  if (hi == x.end()) return y.back();
  if (hi == x.begin()) return y.front();
  const std::size_t j = static_cast<std::size_t>(hi - x.begin());
  const double t = (at - x[j - 1]) / (x[j] - x[j - 1]);
  return y[j - 1] + t * (y[j] - y[j - 1]);
}

struct PureWater {
  Spectrum a, b;
};

const PureWater& pure_water() {
  static const PureWater w = [] {
    const CsvTable t = embedded_table_or_abort("pure_water_absorption_scattering_5nm.csv");
    return PureWater{grid_column_or_abort(t, "a_w_per_m"), grid_column_or_abort(t, "b_sw_smith_baker_per_m")};
  }();
  return w;
}

// One Jerlov column of `quantity` ("a" or "b"), its empty cells filled from the gap-fill table.
std::vector<double> jerlov_column(const CsvTable& table, const CsvTable& gapfill, const std::string& quantity,
                                  const std::string& type) {
  auto cells = table.numbers_or_empty(type);
  if (!cells) abort_table_defect(cells.error().message);
  const std::vector<double> wavelengths = numbers_or_abort(table, "wavelength_nm");
  auto quantities = gapfill.texts("quantity");
  auto types = gapfill.texts("water_type");
  if (!quantities || !types) abort_table_defect(gapfill.source() + ": missing quantity/water_type columns");
  const std::vector<double> fill_nm = numbers_or_abort(gapfill, "wavelength_nm");
  const std::vector<double> fill_value = numbers_or_abort(gapfill, "value_per_m");
  for (std::size_t g = 0; g < fill_nm.size(); ++g) {
    if ((*quantities)[g] != quantity || (*types)[g] != type) continue;
    const auto row = std::find(wavelengths.begin(), wavelengths.end(), fill_nm[g]);
    if (row == wavelengths.end() || (*cells)[row - wavelengths.begin()].has_value())
      abort_table_defect(gapfill.where(g, "value_per_m") + ": does not fill an empty cell of " +
                         table.source());
    (*cells)[row - wavelengths.begin()] = fill_value[g];
  }
  std::vector<double> out;
  for (std::size_t r = 0; r < cells->size(); ++r) {
    if (!(*cells)[r]) abort_table_defect(table.where(r, type) + ": empty and not gap-filled");
    out.push_back(*(*cells)[r]);
  }
  return out;
}

WaterIops build_jerlov(const std::string& type, const CsvTable& a_table, const CsvTable& b_table,
                       const CsvTable& gapfill) {
  const std::vector<double> a_nm = numbers_or_abort(a_table, "wavelength_nm");
  const std::vector<double> b_nm = numbers_or_abort(b_table, "wavelength_nm");
  const std::vector<double> a = jerlov_column(a_table, gapfill, "a", type);
  const std::vector<double> b = jerlov_column(b_table, gapfill, "b", type);
  if (a_nm.back() != kJerlovLastNm || b_nm.back() != kJerlovLastNm)
    abort_table_defect(a_table.source() + ": the Jerlov tables should end at 700 nm");
  const PureWater& w = pure_water();
  const int i700 = static_cast<int>((kJerlovLastNm - kLambdaMinNm) / kLambdaStepNm);
  const double a_nw700 = std::max(0.0, a.back() - w.a[i700]);
  const double b_p700 = std::max(0.0, b.back() - w.b[i700]);
  WaterIops iops{"jerlov-" + type, {}, {}};
  for (int i = 0; i < kSamples; ++i) {
    const double nm = wavelength_nm(i);
    if (nm <= kJerlovLastNm) {
      iops.absorption_per_m[i] = interpolate(a_nm, a, nm);
      iops.scattering_per_m[i] = interpolate(b_nm, b, nm);
    } else {
      iops.absorption_per_m[i] = w.a[i] + a_nw700 * std::exp(-kNonWaterSlopePerNm * (nm - kJerlovLastNm));
      iops.scattering_per_m[i] = w.b[i] + b_p700 * (kJerlovLastNm / nm);
    }
  }
  return iops;
}

const std::vector<WaterIops>& jerlov_types() {
  static const std::vector<WaterIops> types = [] {
    const CsvTable a = embedded_table_or_abort("jerlov_sm2015_a.csv");
    const CsvTable b = embedded_table_or_abort("jerlov_sm2015_b.csv");
    const CsvTable gapfill = embedded_table_or_abort("jerlov_sm2015_gapfill_williamson2022.csv");
    std::vector<WaterIops> out;
    for (const std::string& name : water_type_names())
      out.push_back(build_jerlov(name.substr(std::string("jerlov-").size()), a, b, gapfill));
    return out;
  }();
  return types;
}

// Edit distance, case-insensitive, where swapping look-alikes (digit 1 / letter I / letter l, 0 / O)
// costs half: "jerlov-1b" is closer to "jerlov-IB" than to "jerlov-1C".
double edit_distance(const std::string& s, const std::string& t) {
  auto lower = [](char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); };
  auto substitution = [&](char x, char y) {
    x = lower(x), y = lower(y);
    if (x == y) return 0.0;
    auto one = [](char c) { return c == '1' || c == 'i' || c == 'l'; };
    auto zero = [](char c) { return c == '0' || c == 'o'; };
    return (one(x) && one(y)) || (zero(x) && zero(y)) ? 0.5 : 1.0;
  };
  std::vector<double> prev(t.size() + 1), cur(t.size() + 1);
  for (std::size_t j = 0; j <= t.size(); ++j) prev[j] = static_cast<double>(j);
  for (std::size_t i = 1; i <= s.size(); ++i) {
    cur[0] = static_cast<double>(i);
    for (std::size_t j = 1; j <= t.size(); ++j)
      cur[j] = std::min({prev[j] + 1.0, cur[j - 1] + 1.0, prev[j - 1] + substitution(s[i - 1], t[j - 1])});
    std::swap(prev, cur);
  }
  return prev[t.size()];
}

}  // namespace

const std::vector<std::string>& water_type_names() {
  static const std::vector<std::string> names = {"jerlov-I",   "jerlov-IA", "jerlov-IB", "jerlov-II",
                                                 "jerlov-III", "jerlov-1C", "jerlov-3C", "jerlov-5C",
                                                 "jerlov-7C",  "jerlov-9C"};
  return names;
}

Result<WaterIops> water_type(const std::string& name) {
  const std::vector<std::string>& names = water_type_names();
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return jerlov_types()[i];
  std::string list, closest;
  double best = 1e300;
  for (const std::string& n : names) {
    list += (list.empty() ? "" : ", ") + n;
    const double d = edit_distance(name, n);
    if (d < best) best = d, closest = n;
  }
  return make_error("unknown water type '" + name + "' (did you mean '" + closest +
                    "'?); the water types are: " + list);
}

Result<WaterIops> load_water_table(const std::filesystem::path& csv) {
  auto table = CsvTable::read_file(csv);
  if (!table) return table.error();
  auto nm = table->numbers("wavelength_nm");
  if (!nm) return nm.error();
  auto a = table->numbers("absorption_per_m");
  if (!a) return a.error();
  auto b = table->numbers("scattering_per_m");
  if (!b) return b.error();
  const std::string file = csv.string();
  if (nm->empty()) return make_error(file + ": no data rows");
  for (std::size_t r = 0; r < nm->size(); ++r) {
    if (r > 0 && !((*nm)[r] > (*nm)[r - 1]))
      return make_error(table->where(r, "wavelength_nm") + ": wavelengths must increase from row to row");
    if (!((*a)[r] > 0.0))
      return make_error(table->where(r, "absorption_per_m") + ": " + std::to_string((*a)[r]) +
                        " m^-1; absorption must be > 0");
    if ((*b)[r] < 0.0)
      return make_error(table->where(r, "scattering_per_m") + ": " + std::to_string((*b)[r]) +
                        " m^-1; scattering must be >= 0");
  }
  const double lo = nm->front(), hi = nm->back();
  if (lo > kLambdaMinNm || hi < kLambdaMaxNm) {
    char text[80];
    std::string missing;
    if (lo > kLambdaMinNm && hi > kLambdaMinNm) {
      std::snprintf(text, sizeof text, "%d-%g nm", kLambdaMinNm, std::min(lo, double{kLambdaMaxNm}));
      missing = text;
    }
    if (hi < kLambdaMaxNm && lo < kLambdaMaxNm) {
      std::snprintf(text, sizeof text, "%g-%d nm", std::max(hi, double{kLambdaMinNm}), kLambdaMaxNm);
      missing += (missing.empty() ? "" : " and ") + std::string(text);
    }
    if (missing.empty()) missing = "all of it";
    std::snprintf(text, sizeof text, "%g-%g nm", lo, hi);
    return make_error(file + ": the table covers " + text + ", the water model needs " +
                      std::to_string(kLambdaMinNm) + "-" + std::to_string(kLambdaMaxNm) + " nm; missing " +
                      missing);
  }
  WaterIops iops{csv.stem().string(), {}, {}};
  for (int i = 0; i < kSamples; ++i) {
    iops.absorption_per_m[i] = interpolate(*nm, *a, wavelength_nm(i));
    iops.scattering_per_m[i] = interpolate(*nm, *b, wavelength_nm(i));
  }
  return iops;
}

const Spectrum& pure_water_absorption() {
  return pure_water().a;
}
const Spectrum& pure_seawater_scattering() {
  return pure_water().b;
}

}  // namespace lagoon::optics

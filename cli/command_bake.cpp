// shadetree bake FILE -o FOLDER: a texture graph's texture set (colour,
// alpha, height, normal, roughness: those it outputs, the normal from the
// height's exact gradient where it gives no normal) as images of one size,
// with a JSON sidecar that says what each file holds (render/texture_bake.h).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "graph/file_path.h"
#include "graph/parse.h"
#include "io/graph_files.h"
#include "io/image_output.h"
#include "io/output_file.h"
#include "pipeline/compile_graph.h"
#include "graph/derived_normals.h"
#include "render/texture_bake.h"
#include "schedule/progress.h"

namespace shadetree {

namespace {
struct BakeArguments {
  std::string file;
  std::string folder;
  std::string size;
  std::string domain;
  std::string maps;
  std::string format = "png16";
  std::string normal_convention = "opengl";
  std::optional<float> normal_strength;
  std::string name;
  SamplingArguments sampling;
};

Diagnostic error_in(const std::string& file, const std::string& message) {
  return Diagnostic{ExitStatus::invalid_input, file, {}, {}, message};
}

// The set's file names: the graph's name made safe for every file system.
std::string file_stem(const BakeArguments& arguments, const Graph& graph) {
  std::string stem = !arguments.name.empty() ? arguments.name
                     : !graph.name.empty()   ? graph.name
                                             : std::filesystem::path(arguments.file).stem().string();
  for (char& c : stem)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
  return stem.empty() ? "texture" : stem;
}

bool declares(const Graph& graph, OutputId output) { return find_output(graph, output_id_name(output)) != nullptr; }

// --maps (names, comma-separated), or every map the graph gives.
Result<std::vector<OutputId>> chosen_maps(const std::string& list, const Graph& graph) {
  std::string given;
  for (OutputId output : bakeable_outputs)
    if (declares(graph, output)) given += (given.empty() ? "" : ", ") + std::string(output_id_name(output));
  std::vector<OutputId> maps;
  std::stringstream names(list);
  for (std::string name; std::getline(names, name, ',');) {
    const auto* found = std::find_if(std::begin(bakeable_outputs), std::end(bakeable_outputs),
                                     [&](OutputId output) { return output_id_name(output) == name; });
    if (found == std::end(bakeable_outputs))
      return invalid_input("--maps: \"" + printable(name) + "\" is not a map bake writes (color, alpha, height, normal, roughness)");
    if (!declares(graph, *found))
      return invalid_input("--maps: the graph gives no " + name + (*found == OutputId::normal ? " and no height" : "") +
                           " (it gives " + given + ")");
    if (std::find(maps.begin(), maps.end(), *found) == maps.end()) maps.push_back(*found);
  }
  if (!list.empty()) return maps;
  for (OutputId output : bakeable_outputs)
    if (declares(graph, output)) maps.push_back(output);
  return maps;
}

// Heights in a PNG span its whole range: the sidecar gives the heights of
// its 0 and 1.
std::pair<float, float> range_of(const Image& image) {
  const auto [low, high] = std::minmax_element(image.pixels.begin(), image.pixels.end());
  return {*low, *high};
}

Image normalized(const Image& image, std::pair<float, float> range) {
  Image result = image;
  const float span = range.second - range.first;
  for (float& value : result.pixels) value = span > 0.0f ? (value - range.first) / span : 0.0f;
  return result;
}

ExitStatus bake(const BakeArguments& arguments) {
  Result<Graph> parsed = load_graph(arguments.file);
  if (!parsed) return report(parsed.error());
  if (parsed->kind != GraphKind::texture)
    return report(error_in(arguments.file, "bake renders texture graphs; this is " + a_graph_of(parsed->kind)));
  // As for render's outputs: a folder that is not there is exit status 1.
  const std::filesystem::path folder(arguments.folder);
  if (Status text = check_path_text(arguments.folder, "output folder"); !text) return report(text.error());
  std::error_code ignored;
  if (!std::filesystem::is_directory(folder, ignored))
    return report(failure("output folder \"" + arguments.folder + "\" " +
                          (std::filesystem::exists(folder, ignored) ? "is not a folder" : "does not exist")));
  Result<TextureView> view = texture_view(*parsed, arguments.size, arguments.sampling.frame);
  if (!view) return report(view.error());
  if (!arguments.domain.empty()) {
    Result<std::vector<float>> corners = parse_floats(arguments.domain, 4, "--domain");
    if (!corners) return report(corners.error());
    const auto& d = *corners;
    if (!(d[0] < d[2] && d[1] < d[3]) || std::fabs(d[2] - d[0]) > 1e6f || std::fabs(d[3] - d[1]) > 1e6f)
      return report(invalid_input("--domain expects MINX,MINY,MAXX,MAXY with MIN < MAX, spans at most 1e6, got \"" +
                                  printable(arguments.domain) + "\""));
    view->domain_min[0] = d[0];
    view->domain_min[1] = d[1];
    view->domain_max[0] = d[2];
    view->domain_max[1] = d[3];
  }
  const float strength = arguments.normal_strength.value_or(1.0f);
  if (strength < 0.0f || strength > 1000.0f)
    return report(invalid_input("--normal-strength must be in [0, 1000], got " + std::to_string(strength)));
  const bool normal_from_height = declares(*parsed, OutputId::height) && !declares(*parsed, OutputId::normal);
  const Graph graph = with_normal_from_height(std::move(*parsed), strength);
  Result<std::vector<OutputId>> maps = chosen_maps(arguments.maps, graph);
  if (!maps) return report(error_in(arguments.file, maps.error().message));
  if (maps->empty()) return report(error_in(arguments.file, "the graph gives no map to bake"));
  Result<LoadedGraph> loaded = compile_graph(graph, arguments.sampling.assignments, graph_files(arguments.sampling.search_paths));
  if (!loaded) return report(loaded.error());
  Result<std::unique_ptr<Kernel>> kernel = make_kernel(arguments.sampling.backend, loaded->ir, 0);
  if (!kernel) return report(kernel.error());

  ProgressReporter progress("baking " + arguments.file, "tiles", "samples");
  TextureRenderOptions options;
  options.threads = arguments.sampling.threads;
  options.progress = progress.callback();
  const auto start = std::chrono::steady_clock::now();
  Result<BakedSet> set = bake_texture_set(**kernel, loaded->params, *view, *maps, options);
  if (!set) return report(error_in(arguments.file, set.error().message));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const std::string stem = file_stem(arguments, graph);
  const bool exr = arguments.format == "exr";
  const int png_bits = arguments.format == "png" ? 8 : 16;
  const auto convention =
      arguments.normal_convention == "directx" ? NormalConvention::directx : NormalConvention::opengl;
  nlohmann::ordered_json sidecar;
  sidecar["format"] = "shadetree-texture-set";
  sidecar["version"] = 1;
  sidecar["graph"] = arguments.file;
  sidecar["size"] = {view->width, view->height};
  sidecar["domain"] = {{"min", {view->domain_min[0], view->domain_min[1]}},
                       {"max", {view->domain_max[0], view->domain_max[1]}},
                       {"z", view->z}};
  sidecar["frame"] = view->frame;
  sidecar["tileable"] = set->tileable;
  std::string names;
  for (const BakedMap& map : set->maps) {
    const std::string name(output_id_name(map.output));
    const std::string file = stem + "_" + name + (exr ? ".exr" : ".png");
    nlohmann::ordered_json entry;
    entry["file"] = file;
    Image pixels = map.image;
    if (map.output == OutputId::normal) {
      pixels = encoded_normal_map(map.image, convention);
      entry["space"] = "tangent: x along the columns, y up the rows, z out of the texture";
      entry["convention"] = arguments.normal_convention;
      entry["encoding"] = "0.5 n + 0.5";
      if (normal_from_height) entry["from_height"] = {{"strength", strength}};
    } else if (map.output == OutputId::height) {
      const auto range = range_of(map.image);
      entry["units"] = "P";
      entry["range"] = {range.first, range.second};
      if (!exr) {
        pixels = normalized(map.image, range);
        entry["encoding"] = "range[0] + pixel (range[1] - range[0])";
      }
    } else if (!exr) {
      entry["encoding"] = "clamped to [0, 1]";
    }
    Status written = write_image(pixels, (folder / file).string(), png_bits);
    if (!written) return report(written.error());
    sidecar["maps"][name] = entry;
    names += (names.empty() ? "" : ", ") + name;
  }
  const std::string sidecar_path = (folder / (stem + ".json")).string();
  Status written = write_then_rename(sidecar_path, [&](const std::string& temporary) -> std::string {
    std::ofstream out(temporary);
    out << sidecar.dump(2) << "\n";
    out.close();
    return out ? std::string() : "cannot write " + temporary;
  });
  if (!written) return report(written.error());
  std::fprintf(stderr, "%s: %zu maps of %dx%d (%s), %s, baked in %.3f s -> %s\n", arguments.file.c_str(),
               set->maps.size(), view->width, view->height, names.c_str(),
               set->tileable ? "tileable" : "not tileable", seconds, sidecar_path.c_str());
  return ExitStatus::ok;
}
}  // namespace

void add_bake_command(CLI::App& app, CommandRunner& run) {
  auto* command = app.add_subcommand(
      "bake", "write a texture graph's texture set (color, alpha, height, normal, roughness maps) and a JSON sidecar");
  auto arguments = std::make_shared<BakeArguments>();
  command->add_option("file", arguments->file, "graph file (a texture graph)")->required();
  command->add_option("-o,--output", arguments->folder, "folder to write the set into (must exist)")->required();
  command->add_option("--size", arguments->size, "image size WIDTHxHEIGHT (default: the graph's)");
  command->add_option("--domain", arguments->domain,
                      "P.xy at the lower-left and upper-right corners, MINX,MINY,MAXX,MAXY (default: the graph's); "
                      "a whole number of the graph's periods makes the set tile");
  command->add_option("--maps", arguments->maps,
                      "maps to write, comma-separated: color, alpha, height, normal, roughness (default: all the "
                      "graph gives; normal also from a height)");
  command->add_option("--format", arguments->format, "png (8-bit), png16 (16-bit, the default) or exr (32-bit float)")
      ->check(CLI::IsMember({"png", "png16", "exr"}));
  command->add_option("--normal-convention", arguments->normal_convention,
                      "green channel of the normal map: opengl (up the texture, the default) or directx (down)")
      ->check(CLI::IsMember({"opengl", "directx"}));
  add_finite_option(*command, "--normal-strength", arguments->normal_strength,
                    "normal from a height: slopes scaled by this, 0 to 1000 (default 1)");
  command->add_option("--name", arguments->name, "file names' prefix (default: the graph's name)");
  add_sampling_options(*command, arguments->sampling);
  command->callback([&run, arguments] { run = [arguments] { return bake(*arguments); }; });
}

}  // namespace shadetree

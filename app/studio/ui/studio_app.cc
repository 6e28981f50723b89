#include "app/studio/ui/studio_app.h"

#include <GL/glcorearb.h>
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdlib>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/studio/editor/canvas_layout.h"
#include "app/studio/editor/document.h"
#include "app/studio/editor/eval_worker.h"
#include "app/studio/editor/export_meshes.h"
#include "app/studio/editor/glb_loader.h"
#include "app/studio/editor/session_files.h"
#include "app/studio/editor/thread_cpu.h"
#include "app/studio/ui/back_buffer_age.h"
#include "app/studio/ui/copy_sub_buffer.h"
#include "app/studio/ui/inspector.h"
#include "app/studio/ui/layout_settings.h"
#include "app/studio/ui/key_input.h"
#include "app/studio/ui/mouse_input.h"
#include "app/studio/ui/widget_rects.h"
#include "app/studio/ui/node_canvas.h"
#include "app/studio/ui/partial_redraw.h"
#include "app/studio/ui/preview_view.h"
#include "app/studio/ui/recipe_panel.h"
#include "app/studio/ui/screenshot.h"
#include "app/studio/ui/shape_editor.h"
#include "app/cli/feature_binding.h"
#include "core/io/footprint_read.h"
#include "core/io/geojson.h"
#include "core/io/gltf_write.h"
#include "graph/pxg.h"

namespace procex::studio {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

double ms_since(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

// A file chooser without a native dialog: a path field and the folder's recipes.
struct PathPrompt {
  enum class Kind { kNone, kOpen, kSaveAs, kExport } kind = Kind::kNone;
  std::string path;
  bool open_requested = false;
};

// The formats File > Export writes, as the buttons under its path name them.
const char* format_label(const std::string& extension) {
  if (extension == ".glb") return "glTF (.glb)";
  if (extension == ".obj") return "OBJ + MTL (.obj)";
  if (extension == ".ply") return "PLY (.ply)";
  if (extension == ".gpkg") return "GeoPackage (.gpkg)";
  if (extension == ".json") return "CityJSON (.json)";
  return extension.c_str();
}

// "loading city.glb (120.0 MB): reading", then "...: making the preview".
std::string glb_progress_text(const GlbLoader::Progress& p) {
  char size[32];
  std::snprintf(size, sizeof size, "%.1f MB", static_cast<double>(p.size) / 1e6);
  return "loading " + p.file.filename().string() + " (" + size + "): " + (p.preparing ? "making the preview" : "reading");
}

}  // namespace

class App {
 public:
  App(GLFWwindow* window, const Options& options)
      : window_(window), options_(options), home_(studio_home()), recent_(home_ / "recent.txt"),
        interactive_(options_.screenshot.empty() && options_.bench_edits == 0) {
    const bool interactive = interactive_;
    canvas_.show_times(options_.screenshot.empty());
    // Screenshots and benchmarks show the default layout, whatever this user made of theirs.
    keep_layout_ = interactive;
    if (options_.recipe.extension() == ".glb") {
      doc_ = std::make_unique<Document>();
      view_glb(options_.recipe);
    } else if (!options_.recipe.empty()) {
      load(options_.recipe, interactive);
      if (doc_->graph().node(options_.select)) doc_->select_only(options_.select);
    } else {
      doc_ = std::make_unique<Document>();
      if (interactive && find_recovery(home_, {})) recovery_ = fs::path();
    }
    if (!options_.footprints.empty() && !bind_footprints(options_.footprints)) {
      std::fprintf(stderr, "procex-studio: %s\n", status_.c_str());
      if (!interactive) load_failed_ = true;  // a screenshot or benchmark of other buildings would mislead
    }
    if (keep_layout_)
      if (std::string failed = layout_.load(); !failed.empty()) status_ = std::move(failed);
  }

  // Whether the last finished evaluation is of the current revision and its preview is on screen (and no .glb is loading).
  bool settled() const {
    return worker_.idle() && !glb_loader_.progress() && shown_ && shown_->revision == doc_->revision() && submitted_ == doc_->revision() &&
           preview_ && preview_->current();
  }
  bool busy() const { return !worker_.idle() || loading_glb(); }
  // Whether this frame put a panel elsewhere than the last frame did. The first frame places
  // the panels before ImGui has measured the menu bar (the viewport's work area shrinks to
  // below it a frame later), so everything moves down in the second: that frame is drawn at
  // once rather than at the next event, and the ui map calls nothing settled until the
  // panels stand still (a click aimed from the first frame's map landed above its button).
  bool layout_moving() const { return layout_moving_; }
  bool loading_glb() const { return glb_loader_.progress().has_value(); }
  // Stops the evaluation; false if it is still running after `timeout` (a node that never polls cancellation).
  bool stop_evaluation(std::chrono::milliseconds timeout) {
    worker_.cancel();
    return worker_.wait_idle(timeout);
  }
  bool load_failed() const { return load_failed_; }
  // What the preview shows: a viewed .glb, else the recipe's last evaluation.
  const PreviewMesh* on_screen() const { return viewed_ ? viewed_->mesh.get() : shown_ && shown_->preview ? shown_->preview.get() : nullptr; }
  Document& doc() { return *doc_; }
  const EvalSnapshot* shown() const { return shown_.get(); }
  const PreviewView& preview() const { return *preview_; }
  double preview_render_cpu_ms() const { return preview_ ? preview_->render_cpu_ms() : 0.0; }
  // An image of the preview asked for and not yet shown: its thread wakes the loop when it is finished.
  bool preview_pending() const { return preview_ && !preview_->current(); }
  // Whether the preview's thread is drawing an image, and how many it has finished.
  bool preview_drawing() const { return preview_ && preview_->drawing(); }
  std::uint64_t preview_images() const { return preview_ ? preview_->images_finished() : 0; }
  const NodeCanvas& canvas() const { return canvas_; }

  void frame() {
    if (!preview_) {
      preview_ = std::make_unique<PreviewView>(window_);
      if (options_.view) preview_->look_from((*options_.view)[0], (*options_.view)[1]);
    }
    submit_if_changed();  // what changed between frames (a file opened, the benchmark's edit)
    // An edit of the recipe brings its preview back in place of a viewed .glb.
    if (viewed_ && viewed_->revision != doc_->revision()) close_glb();
    if (auto latest = worker_.latest(); latest && latest != shown_) {
      shown_ = std::move(latest);
      if (!viewed_) preview_->set_mesh(shown_->preview);
    }
    if (here_of_ != std::pair(shown_, doc_->scope())) {
      here_of_ = {shown_, doc_->scope()};
      here_ = shown_ && !doc_->scope().empty() ? std::make_shared<const EvalSnapshot>(inside_group(*shown_, doc_->scope())) : shown_;
    }
    if (auto loaded = glb_loader_.take()) glb_loaded(*loaded);
    if (viewed_) preview_->set_mesh(viewed_->mesh);
    autosave();
    if (keep_layout_ && ImGui::GetIO().WantSaveIniSettings)
      if (std::string failed = layout_.save(); !failed.empty()) status_ = std::move(failed);
    buttons_.clear();
    shortcuts();
    menu_bar();
    layout_windows();
    modals();
    // This frame's edits go to the worker now, not at the next frame's start: with nothing queued
    // the loop sleeps until an event (a key's release comes only when the person lets go) or 0.25 s.
    submit_if_changed();
    update_title();
    if (!options_.ui_map.empty()) write_ui_map();
    doc_->end_frame();
  }

  // Files dropped onto the window: a .glb is viewed, a recipe opens (after
  // asking about unsaved changes); any other file is read as footprints (bind_footprints).
  void open_dropped(const fs::path& file) {
    if (file.extension() == ".glb") {
      view_glb(file);
      return;
    }
    if (file.extension() == ".pxg") {
      confirm_discard([this, file] { load(file, true); });
      return;
    }
    if (!bind_footprints(file)) status_ += " (drop a recipe (.pxg) to open it, a .glb to view it, or a footprint file to preview its buildings)";
  }

  // A footprint file (core/io/footprint_read.h: GeoJSON, Shapefile,
  // GeoPackage, FlatGeobuf, OSM) as the preview's input: every feature read,
  // with the party and street edges procex batch finds when the recipe reads
  // them, each bound to the recipe and shown where it stands. False, with the
  // reason in the status bar, when no feature could be read.
  bool bind_footprints(const fs::path& file) {
    try {
      GeoJsonCollection c = read_footprints(file);
      if (c.features.empty()) {
        status_ = file.string() + ": no feature could be read" + (c.errors.empty() ? "" : " (" + c.errors.front().message + ")");
        return false;
      }
      const std::size_t n = c.features.size();
      preview_footprint_source_ = n == 1 ? file.string() + "#" + c.features.front().id : file.string() + " (" + std::to_string(n) + " features)";
      const std::string not_read = c.errors.empty() ? "" : "; " + std::to_string(c.errors.size()) + " features not read (" + c.errors.front().message + ")";
      footprints_ = std::make_shared<const GeoJsonCollection>(std::move(c));
      labelled_for_.reset();
      label_footprints();
      submitted_ = 0;  // evaluate again with the new plans
      if (preview_) preview_->frame_next_mesh();  // the buildings stand elsewhere than the stand-in did
      status_ = "footprint input: " + preview_footprint_source_ + not_read;
      return true;
    } catch (const std::exception& e) {
      status_ = e.what();
      return false;
    }
  }

  // The footprints' party and street edges, as the recipe now open reads them: made again when
  // another recipe (or an edit) reads other ones, as procex batch would make them for it.
  void label_footprints() {
    if (!footprints_) return;
    const EdgeLabelsRead reads = edge_labels_read(doc_->recipe());
    if (labelled_for_ == reads) return;
    labelled_for_ = reads;
    GeoJsonCollection c = *footprints_;
    add_edge_labels(doc_->recipe(), c);
    preview_features_ = std::make_shared<const std::vector<GeoJsonFeature>>(std::move(c.features));
  }

  // Close button: ask first when there are unsaved changes.
  void request_quit() {
    glfwSetWindowShouldClose(window_, GLFW_FALSE);
    confirm_discard([this] { quit_ = true; });
  }
  bool quit() const { return quit_; }
  void leave() {
    // A clean exit leaves no autosave behind unless edits are unsaved.
    if (!doc_->dirty()) remove_autosave(home_, doc_->path());
    if (keep_layout_) (void)layout_.save();  // nowhere left to say that it failed
  }

 private:
  // The recipe to the evaluation thread when it or the selection changed since it was last sent.
  void submit_if_changed() {
    if (submitted_ == doc_->revision() && submitted_node_ == doc_->selected()) return;
    submitted_ = doc_->revision();
    submitted_node_ = doc_->selected();
    label_footprints();
    // The selected node's outputs too, for the plan and profile editors (cached: cheap).
    // (Those of a node inside a group are no ports of the recipe: inside a group there are none.)
    std::vector<PortRef> extra;
    if (const Node* n = doc_->scope().empty() ? doc_->graph().node(submitted_node_) : nullptr)
      for (std::uint32_t i = 0; i < n->decl().outputs().size(); ++i) extra.push_back({submitted_node_, i});
    worker_.submit(submitted_, doc_->recipe(), extra, preview_bindings(doc_->recipe(), preview_footprint()),
                   doc_->path().empty() ? fs::path() : fs::absolute(doc_->path()).parent_path(), preview_features_);
  }

  // A .glb procex wrote, shown in the preview in place of the recipe's (read
  // only) until the recipe is edited or View > Recipe preview. The recipe
  // stays open. It is read on the loader's thread (glb_loaded takes it); a
  // file the reader refuses changes nothing and the status says why.
  void view_glb(const fs::path& file) {
    glb_loader_.load(file);
    status_ = "loading " + file.string();
  }

  void glb_loaded(const GlbLoader::Loaded& loaded) {
    if (!loaded.mesh) {
      status_ = loaded.error;
      std::fprintf(stderr, "procex-studio: %s\n", loaded.error.c_str());
      load_failed_ = !viewed_ && options_.recipe == loaded.file;
      return;
    }
    const PreviewMesh& mesh = *loaded.mesh;
    status_ = "viewing " + loaded.file.string() + ": " + std::to_string(mesh.meshes) + (mesh.meshes == 1 ? " building, " : " buildings, ") +
              std::to_string(mesh.faces) + " faces (read only; View > Recipe preview or an edit shows the recipe again)";
    viewed_ = ViewedGlb{loaded.file, loaded.mesh, doc_->revision()};
    if (preview_) preview_->frame_next_mesh();
    if (interactive_) recent_.add(loaded.file);
    load_failed_ = false;
  }

  void close_glb() {
    viewed_.reset();
    if (!preview_) return;
    preview_->frame_next_mesh();
    preview_->set_mesh(shown_ ? shown_->preview : nullptr);
  }

  void open_file(const fs::path& file) {
    if (file.extension() == ".glb") view_glb(file);
    else load(file, true);
  }

  void load(const fs::path& file, bool interactive) {
    try {
      doc_ = Document::open(file);
      if (interactive) {
        recent_.add(file);
        if (find_recovery(home_, file)) recovery_ = file;
      }
      status_ = "opened " + file.string();
      canvas_.request_frame();
      load_failed_ = false;
    } catch (const std::exception& e) {
      status_ = e.what();
      std::fprintf(stderr, "procex-studio: %s\n", e.what());
      if (!doc_) doc_ = std::make_unique<Document>();
      load_failed_ = true;
    }
  }

  void confirm_discard(std::function<void()> action) {
    if (!doc_->dirty()) {
      action();
      return;
    }
    pending_ = std::move(action);
    confirm_requested_ = true;
  }

  void save(bool as) {
    if (as || doc_->path().empty()) {
      prompt_ = {PathPrompt::Kind::kSaveAs, doc_->path().empty() ? "untitled.pxg" : doc_->path().string(), true};
      return;
    }
    try {
      remove_autosave(home_, doc_->path());
      doc_->save();
      recent_.add(doc_->path());
      status_ = "saved " + doc_->path().string();
    } catch (const std::exception& e) {
      status_ = e.what();
    }
  }

  void export_meshes(const fs::path& file) {
    if (!settled() || !shown_) {
      status_ = "the recipe is still evaluating: export when the preview is up to date";
      return;
    }
    Result<std::size_t> written = studio::export_meshes(doc_->recipe(), *shown_, file, export_options_);
    status_ = written ? "exported " + std::to_string(*written) + (*written == 1 ? " mesh to " : " meshes to ") + file.string() : written.message();
  }

  void open_export_prompt() {
    const fs::path p = doc_->path().empty() ? fs::path("untitled") : fs::path(doc_->path());
    prompt_ = {PathPrompt::Kind::kExport, fs::path(p).replace_extension(export_extension_).string(), true};
  }

  void autosave() {
    if (options_.autosave_s <= 0 || !options_.screenshot.empty()) return;
    if (Clock::now() - last_autosave_ < std::chrono::seconds(options_.autosave_s)) return;
    last_autosave_ = Clock::now();
    if (autosaved_ == doc_->revision() || !doc_->dirty()) return;
    try {
      write_autosave(home_, doc_->path(), to_pxg(doc_->recipe()));
      autosaved_ = doc_->revision();
    } catch (const std::exception& e) {
      status_ = std::string("autosave failed: ") + e.what();
    }
  }

  void shortcuts() {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantTextInput || !io.KeyCtrl) return;
    if (ImGui::IsKeyPressed('Z')) {
      if (io.KeyShift) doc_->redo();
      else doc_->undo();
    }
    if (ImGui::IsKeyPressed('Y')) doc_->redo();
    if (ImGui::IsKeyPressed('S')) save(io.KeyShift);
    if (ImGui::IsKeyPressed('O')) confirm_discard([this] { prompt_ = {PathPrompt::Kind::kOpen, folder().string() + "/", true}; });
    if (ImGui::IsKeyPressed('N')) confirm_discard([this] { new_document(); });
    if (ImGui::IsKeyPressed('Q')) request_quit();
    if (ImGui::IsKeyPressed('E')) open_export_prompt();
  }

  fs::path folder() const { return doc_->path().empty() ? fs::current_path() : fs::absolute(doc_->path()).parent_path(); }

  void new_document() {
    doc_ = std::make_unique<Document>();
    canvas_.request_frame();
    status_ = "new recipe";
  }

  void menu_bar() {
    if (!ImGui::BeginMainMenuBar()) return;
    const bool file_menu = ImGui::BeginMenu("File");
    record_button("menu_file");
    if (file_menu) {
      if (ImGui::MenuItem("New", "Ctrl+N")) confirm_discard([this] { new_document(); });
      if (ImGui::MenuItem("Open...", "Ctrl+O")) confirm_discard([this] { prompt_ = {PathPrompt::Kind::kOpen, folder().string() + "/", true}; });
      const bool recent_menu = ImGui::BeginMenu("Open recent", !recent_.list().empty());
      record_button("menu_open_recent");
      if (recent_menu) {
        for (std::size_t i = 0; i < recent_.list().size(); ++i) {
          const fs::path f = recent_.list()[i];
          // A .glb is viewed beside the recipe: nothing to discard.
          if (ImGui::MenuItem(f.string().c_str())) {
            if (f.extension() == ".glb") view_glb(f);
            else confirm_discard([this, f] { load(f, true); });
          }
          record_button("recent_" + std::to_string(i));
        }
        ImGui::EndMenu();
      }
      if (ImGui::MenuItem("Save", "Ctrl+S")) save(false);
      if (ImGui::MenuItem("Save as...", "Ctrl+Shift+S")) save(true);
      if (ImGui::MenuItem("Export...", "Ctrl+E")) open_export_prompt();
      record_button("menu_export");
      ImGui::Separator();
      if (ImGui::MenuItem("Quit", "Ctrl+Q")) request_quit();
      ImGui::EndMenu();
    }
    const bool edit_menu = ImGui::BeginMenu("Edit");
    record_button("menu_edit");
    if (edit_menu) {
      if (ImGui::MenuItem(("Undo " + doc_->undo_label()).c_str(), "Ctrl+Z", false, doc_->can_undo())) doc_->undo();
      if (ImGui::MenuItem(("Redo " + doc_->redo_label()).c_str(), "Ctrl+Shift+Z", false, doc_->can_redo())) doc_->redo();
      ImGui::Separator();
      if (ImGui::MenuItem("Delete", "Delete", false, !doc_->selection().empty()))
        if (Status s = doc_->remove_selection(); !s) status_ = s.message();
      if (ImGui::MenuItem("Group selected", "Ctrl+G", false, !doc_->selection().empty()))
        if (auto r = doc_->group_selection(); !r) status_ = r.message();
      {
        const Node* sel = doc_->graph().node(doc_->selected());
        if (ImGui::MenuItem("Ungroup", nullptr, false, sel && !sel->group.empty()))
          if (auto r = doc_->ungroup_selection(); !r) status_ = r.message();
        if (ImGui::MenuItem("Save group to library", nullptr, false, sel && !sel->group.empty())) {
          const Result<fs::path> saved = doc_->save_group_to_library();
          status_ = saved ? "saved group '" + sel->group + "' to " + (*saved).string() : saved.message();
        }
        record_button("menu_save_group");
      }
      if (ImGui::MenuItem("Tidy layout", "L"))
        if (Status s = doc_->tidy_layout(); !s) status_ = s.message();
      ImGui::EndMenu();
    }
    const bool view_menu = ImGui::BeginMenu("View");
    record_button("menu_view");
    if (view_menu) {
      ImGui::MenuItem("Wireframe", nullptr, &preview_->wireframe);
      ImGui::MenuItem("Anchors", nullptr, &preview_->anchors);
      if (ImGui::MenuItem("Frame preview")) preview_->frame_all();
      if (ImGui::MenuItem("Frame nodes", "F")) canvas_.request_frame();
      if (ImGui::MenuItem("Recipe preview", nullptr, false, viewed_.has_value())) close_glb();
      record_button("menu_recipe_preview");
      ImGui::Separator();
      if (ImGui::MenuItem("Reset layout", nullptr, false, keep_layout_)) {
        const std::string failed = layout_.reset();
        status_ = failed.empty() ? "panel layout reset (" + layout_.file().string() + ")" : failed;
      }
      record_button("menu_reset_layout");
      ImGui::EndMenu();
    }
    ImGui::EndMainMenuBar();
  }

  // The four panels meet at the layout's two splits; dragging a panel's inner
  // edge moves its split (its outer edges snap back the next frame).
  void layout_windows() {
    const ImGuiViewport* vp = ImGui::GetMainViewport();
    const float top = vp->WorkPos.y, status_h = ImGui::GetFrameHeight() + 4.0f;
    const float w = vp->WorkSize.x, h = vp->WorkSize.y - status_h;
    PanelLayout& layout = layout_.layout();
    const PanelLayout before = layout;
    const float left_w = std::floor(w * static_cast<float>(layout.split_x)), upper_h = std::floor(h * static_cast<float>(layout.split_y));
    // With nothing selected the inspector has one line to say: the canvas takes its room.
    const bool inspector_empty = doc_->selection().empty();
    const float canvas_h = inspector_empty ? h - std::floor(ImGui::GetFrameHeight() * 2.5f + 8.0f) : upper_h;
    // NoSavedSettings: the panels' places are the layout's splits, so ImGui's own window entries would only
    // rewrite the .ini whenever a selection moves the inspector's edge.
    const ImGuiWindowFlags fixed =
        ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoSavedSettings;
    // Places a panel at (x, y, ww, hh); after its Begin, `moved` reads which edges the user dragged.
    struct Edges {
      float left, top, right, bottom;
    };
    Edges placed{};
    std::vector<float> placements;  // each panel's edges, in order
    auto place = [&](float x, float y, float ww, float hh) {
      placed = {vp->WorkPos.x + x, top + y, vp->WorkPos.x + x + ww, top + y + hh};
      placements.insert(placements.end(), {placed.left, placed.top, placed.right, placed.bottom});
      ImGui::SetNextWindowPos(ImVec2(placed.left, placed.top));
      ImGui::SetNextWindowSize(ImVec2(ww, hh));
    };
    auto moved = [&](const char* panel) {
      const ImVec2 p = ImGui::GetWindowPos(), s = ImGui::GetWindowSize();
      buttons_[std::string("panel_") + panel] = {p.x, p.y, s.x, s.y};
      return Edges{p.x - placed.left, p.y - placed.top, p.x + s.x - placed.right, p.y + s.y - placed.bottom};
    };
    auto set_x = [&](float edge) { layout.split_x = (edge - vp->WorkPos.x) / w; };
    auto set_y = [&](float edge) { layout.split_y = (edge - top) / h; };
    auto dragged = [](float d) { return d > 0.5f || d < -0.5f; };
    place(0, 0, left_w, canvas_h);
    canvas_has_keys_ = false;
    if (ImGui::Begin("Nodes", nullptr, fixed | ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse)) {
      canvas_has_keys_ = ImGui::IsWindowFocused();
      if (const Edges m = moved("nodes"); dragged(m.right)) set_x(placed.right + m.right);
      else if (!inspector_empty && dragged(m.bottom)) set_y(placed.bottom + m.bottom);
      canvas_.draw(*doc_, here_.get(), status_);
    }
    ImGui::End();
    place(0, canvas_h, left_w, h - canvas_h);
    if (ImGui::Begin("Inspector", nullptr, fixed)) {
      if (const Edges m = moved("inspector"); dragged(m.right)) set_x(placed.right + m.right);
      else if (!inspector_empty && dragged(m.top)) set_y(placed.top + m.top);
      inspector_.draw(*doc_, here_.get(), status_);
    }
    ImGui::End();
    place(left_w, 0, w - left_w, upper_h);
    if (ImGui::Begin("Preview", nullptr, fixed | ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse)) {
      if (const Edges m = moved("preview"); dragged(m.left)) set_x(placed.left + m.left);
      else if (dragged(m.bottom)) set_y(placed.bottom + m.bottom);
      preview_->draw();
    }
    ImGui::End();
    place(left_w, upper_h, w - left_w, h - upper_h);
    if (ImGui::Begin("Evaluation", nullptr, fixed | ImGuiWindowFlags_NoScrollbar)) {
      if (const Edges m = moved("evaluation"); dragged(m.left)) set_x(placed.left + m.left);
      else if (dragged(m.top)) set_y(placed.top + m.top);
      evaluation_panel();
    }
    ImGui::End();
    place(0, h, w, status_h);
    if (ImGui::Begin("##status", nullptr, fixed | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar)) status_bar();
    ImGui::End();
    layout = layout.clamped();
    if (!(layout == before)) layout_.mark_changed();
    layout_moving_ = placements != last_placements_;
    last_placements_ = std::move(placements);
  }

  void evaluation_panel() {
    if (!ImGui::BeginTabBar("eval")) return;
    if (ImGui::BeginTabItem("Plan / Profile")) {
      shape_editor_.draw(*doc_, here_.get(), status_);
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("Recipe")) {
      recipe_panel_.draw(*doc_, status_, [this](const fs::path& png) {
        save_texture_png(static_cast<unsigned>(preview_->texture()), preview_->texture_width(), preview_->texture_height(), png);
      });
      ImGui::EndTabItem();
    }
    const bool library_tab = ImGui::BeginTabItem("Library");
    record_button("tab_library");
    if (library_tab) {
      library_panel();
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("Diagnostics")) {
      if (!shown_ || shown_->result.diagnostics.empty()) ImGui::TextDisabled("No errors or warnings.");
      if (shown_)
        for (const Diagnostic& d : shown_->result.diagnostics) {
          ImGui::PushStyleColor(ImGuiCol_Text, d.severity == Severity::kError ? ImVec4(1, 0.4f, 0.35f, 1) : ImVec4(1, 0.8f, 0.3f, 1));
          if (ImGui::Selectable(d.to_string().c_str()) && !d.node.empty()) show_node(d.node);
          ImGui::PopStyleColor();
        }
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("Anchors")) {
      anchor_list();
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("Statistics")) {
      if (shown_ && ImGui::BeginTable("stats", 4, ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY)) {
        ImGui::TableSetupColumn("node");
        ImGui::TableSetupColumn("type");
        ImGui::TableSetupColumn("outcome");
        ImGui::TableSetupColumn("ms");
        ImGui::TableHeadersRow();
        for (const NodeStats& s : shown_->result.stats.nodes) {
          ImGui::TableNextRow();
          ImGui::TableNextColumn();
          ImGui::TextUnformatted(to_string(s.path).c_str());
          ImGui::TableNextColumn();
          ImGui::TextUnformatted(s.type.c_str());
          ImGui::TableNextColumn();
          ImGui::TextUnformatted(to_string(s.outcome));
          ImGui::TableNextColumn();
          ImGui::Text("%.2f", static_cast<double>(s.time_ns) * 1e-6);
        }
        ImGui::EndTable();
      }
      ImGui::EndTabItem();
    }
    ImGui::EndTabBar();
  }

  // Selects the node at `path`, opening the groups on the way (as far as they open).
  void show_node(const NodePath& path) {
    doc_->leave_group(0);
    for (std::size_t i = 0; i + 1 < path.size(); ++i)
      if (Status s = doc_->enter_group(path[i]); !s) {
        status_ = s.message();
        return;
      }
    if (doc_->graph().node(path.back())) doc_->select_only(path.back());
  }

  // The groups saved beside the recipe (lib/*.pxg), each placed by its button at the canvas's centre or,
  // where nodes are, the nearest spot where it covers none.
  void library_panel() {
    if (doc_->path().empty()) {
      ImGui::TextDisabled("Save the recipe first: its library is the lib folder beside it.");
      return;
    }
    const std::vector<std::string> files = library_files(folder());
    if (files.empty()) ImGui::TextDisabled("No groups in %s/lib: select a group node, Edit > Save group to library.", folder().string().c_str());
    for (const std::string& file : files) {
      ImGui::PushID(file.c_str());
      const bool place = ImGui::Button("Place");
      record_button("library_place_" + fs::path(file).stem().string());
      ImGui::SameLine();
      ImGui::TextUnformatted(file.c_str());
      if (place) {
        const glm::vec2 at = canvas_.view_centre();
        const Result<NodeId> r = doc_->place_library_group(file, at.x, at.y);
        status_ = r ? "placed " + file + " as node " + std::to_string(*r) : r.message();
      }
      ImGui::PopID();
    }
  }

  // Every resolved anchor of the shown meshes; an absent one says why.
  void anchor_list() {
    const PreviewMesh* p = shown_ && shown_->preview ? shown_->preview.get() : nullptr;
    if (!p || p->anchors.empty()) {
      ImGui::TextDisabled("No anchors: Anchor nodes wired into an Extrude's `anchors` input resolve on its mesh.");
      return;
    }
    if (!ImGui::BeginTable("anchors", 4, ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY)) return;
    ImGui::TableSetupColumn("anchor");
    ImGui::TableSetupColumn("building");
    ImGui::TableSetupColumn("edge");
    ImGui::TableSetupColumn("where");
    ImGui::TableHeadersRow();
    for (const PreviewAnchor& a : p->anchors) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(a.anchor.name.c_str());
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(a.building.c_str());
      ImGui::TableNextColumn();
      ImGui::Text("e%d", a.anchor.edge_id);
      ImGui::TableNextColumn();
      const glm::dvec3& o = a.anchor.frame.origin;
      if (a.anchor.present) ImGui::Text("(%.2f, %.2f, %.2f)", o.x, o.y, o.z);
      else ImGui::TextColored(ImVec4(1, 0.8f, 0.3f, 1), "absent: %s", a.anchor.reason.c_str());
    }
    ImGui::EndTable();
  }

  void status_bar() {
    if (const std::optional<GlbLoader::Progress> p = glb_loader_.progress())
      ImGui::TextColored(ImVec4(0.5f, 0.8f, 1.0f, 1.0f), "%s", glb_progress_text(*p).c_str());
    else if (busy()) ImGui::TextColored(ImVec4(0.5f, 0.8f, 1.0f, 1.0f), "evaluating...");
    else if (shown_) {
      std::size_t errors = 0;
      for (const Diagnostic& d : shown_->result.diagnostics) errors += d.severity == Severity::kError;
      ImGui::TextColored(errors ? ImVec4(1, 0.4f, 0.35f, 1) : ImVec4(0.6f, 0.9f, 0.6f, 1), "%zu errors | %.1f ms | %zu computed, %zu cached", errors,
                         shown_->seconds * 1e3, shown_->result.stats.computed(), shown_->result.stats.count(NodeOutcome::kCacheHit));
    }
    ImGui::SameLine(0, 24);
    ImGui::TextUnformatted(status_.c_str());
  }

  // The last item's rectangle, for the --ui-map.
  void record_button(const std::string& name) { record_item(buttons_, name); }

  void modals() {
    if (confirm_requested_) {
      ImGui::OpenPopup("Unsaved changes");
      confirm_requested_ = false;
    }
    if (ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
      ImGui::Text("%s has unsaved changes.", doc_->title().c_str());
      if (ImGui::Button("Discard them")) {
        ImGui::CloseCurrentPopup();
        remove_autosave(home_, doc_->path());
        auto action = std::move(pending_);
        if (action) action();
      }
      ImGui::SameLine();
      if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
      ImGui::EndPopup();
    }
    if (recovery_) {
      ImGui::OpenPopup("Recover");
    }
    if (ImGui::BeginPopupModal("Recover", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
      const fs::path recipe = recovery_.value_or(fs::path());
      ImGui::Text("Unsaved edits of %s were autosaved (the studio did not close cleanly).", recipe.empty() ? "an untitled recipe" : recipe.string().c_str());
      const bool recover = ImGui::Button("Recover them");
      record_button("recover");
      if (recover) {
        try {
          std::ifstream in(autosave_path(home_, recipe));
          const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
          doc_ = Document::recovered(parse_pxg(text, recipe.empty() ? fs::path("untitled.pxg") : recipe), recipe);
          canvas_.request_frame();
          status_ = "recovered the autosaved edits: save to keep them";
        } catch (const std::exception& e) {
          status_ = std::string("cannot recover: ") + e.what();
        }
        recovery_.reset();
        ImGui::CloseCurrentPopup();
      }
      ImGui::SameLine();
      const bool discard = ImGui::Button("Discard them");
      record_button("discard_autosave");
      if (discard) {
        remove_autosave(home_, recipe);
        recovery_.reset();
        ImGui::CloseCurrentPopup();
      }
      ImGui::EndPopup();
    }
    path_prompt();
  }

  void path_prompt() {
    static const char* kTitles[] = {"", "Open recipe", "Save recipe as", "Export"};
    const char* title = kTitles[static_cast<int>(prompt_.kind)];
    if (prompt_.open_requested) {
      ImGui::OpenPopup(title);
      prompt_.open_requested = false;
    }
    if (prompt_.kind == PathPrompt::Kind::kNone || !ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    ImGui::SetNextItemWidth(520);
    bool go = ImGui::InputText("##path", &prompt_.path, ImGuiInputTextFlags_EnterReturnsTrue);
    record_button("prompt_path");
    const bool exporting = prompt_.kind == PathPrompt::Kind::kExport;
    if (exporting) export_options();
    // The folder's recipes (or exported files), to pick from.
    const fs::path dir = fs::path(prompt_.path).has_parent_path() ? fs::path(prompt_.path).parent_path() : fs::current_path();
    ImGui::BeginChild("files", ImVec2(520, 160), true);
    std::error_code ec;
    std::vector<fs::path> files;
    const std::vector<std::string>& listed = exporting ? export_extensions() : std::vector<std::string>{".pxg", ".glb"};
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
      if (std::count(listed.begin(), listed.end(), it->path().extension().string())) files.push_back(it->path());
    std::sort(files.begin(), files.end());
    for (const fs::path& f : files)
      if (ImGui::Selectable(f.filename().string().c_str())) prompt_.path = f.string();
    ImGui::EndChild();
    go |= ImGui::Button(prompt_.kind == PathPrompt::Kind::kOpen ? "Open" : exporting ? "Export" : "Save");
    record_button("prompt_ok");
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) {
      prompt_.kind = PathPrompt::Kind::kNone;
      ImGui::CloseCurrentPopup();
    }
    if (go && !prompt_.path.empty()) {
      const fs::path p = prompt_.path;
      switch (prompt_.kind) {
        case PathPrompt::Kind::kOpen: open_file(p); break;
        case PathPrompt::Kind::kSaveAs:
          try {
            remove_autosave(home_, doc_->path());
            doc_->save_as(p);
            recent_.add(p);
            status_ = "saved " + p.string();
          } catch (const std::exception& e) {
            status_ = e.what();
          }
          break;
        case PathPrompt::Kind::kExport: export_meshes(p); break;
        case PathPrompt::Kind::kNone: break;
      }
      prompt_.kind = PathPrompt::Kind::kNone;
      ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  }

  // Under the export path: the format (it sets the path's extension), the up
  // axis for OBJ and PLY, the CRS for GeoPackage, CityJSON and glTF: procex eval's -o, --up and --crs.
  void export_options() {
    const std::string now = fs::path(prompt_.path).extension().string();
    for (const std::string& ext : export_extensions()) {
      if (&ext != &export_extensions().front()) ImGui::SameLine();
      if (ImGui::RadioButton(format_label(ext), now == ext)) {
        prompt_.path = fs::path(prompt_.path).replace_extension(ext).string();
        export_extension_ = ext;
      }
      record_button("export_format" + ext);
    }
    if (now == ".obj" || now == ".ply") {
      ImGui::TextUnformatted("up axis:");
      ImGui::SameLine();
      if (ImGui::RadioButton("+Y (Blender, Maya, Houdini)", export_options_.up == UpAxis::Y)) export_options_.up = UpAxis::Y;
      ImGui::SameLine();
      if (ImGui::RadioButton("+Z (GIS)", export_options_.up == UpAxis::Z)) export_options_.up = UpAxis::Z;
      record_button("export_up_z");
    }
    if (now == ".gpkg" || now == ".json" || now == ".glb") {  // the GIS formats; a .glb's is optional
      ImGui::SetNextItemWidth(260);
      ImGui::InputTextWithHint("CRS", "EPSG:32632 (projected, in metres)", &export_options_.crs);
      record_button("export_crs");
    }
  }

  // Pins, parameter widgets and state in window pixels, rewritten when they change.
  void write_ui_map() {
    int wx = 0, wy = 0;
    glfwGetWindowPos(window_, &wx, &wy);
    nlohmann::json j;
    j["window"] = {wx, wy};
    j["revision"] = doc_->revision();
    // The revision the evaluation thread was last given. The map is written after the frame has sent
    // its own edits (submit_if_changed), so it is never behind `revision` here: an edit does not wait
    // for the next frame, which comes only with the next event (a held key's release) or wake-up.
    j["sent"] = submitted_;
    j["settled"] = settled() && !layout_moving_;
    j["dirty"] = doc_->dirty();
    j["selected"] = doc_->selected();
    // Where keys go: the canvas's shortcuts, or a text field (typed characters); tests type once they do.
    j["keyboard"] = {{"canvas", canvas_has_keys_}, {"text", ImGui::GetIO().WantTextInput}};
    j["scope"] = doc_->scope();
    j["breadcrumb"] = doc_->breadcrumb();
    const Rect c = canvas_.screen_rect();
    j["canvas"] = {c.min.x, c.min.y, c.max.x - c.min.x, c.max.y - c.min.y};
    j["canvas_zoom"] = canvas_.zoom();
    j["layout"] = {layout_.layout().split_x, layout_.layout().split_y};
    j["canvas_min_text_px"] = canvas_.min_text_px();
    j["node_positions"] = nlohmann::json::object();
    for (const auto& [id, n] : doc_->graph().nodes()) j["node_positions"][std::to_string(id)] = {n.editor.x, n.editor.y};
    j["node_rects"] = nlohmann::json::object();  // canvas units, the graph's input / output boxes too
    for (const NodeBox& b : layout(doc_->graph()))
      j["node_rects"][std::to_string(b.id)] = {b.rect.min.x, b.rect.min.y, b.rect.max.x - b.rect.min.x, b.rect.max.y - b.rect.min.y};
    j["pins"] = nlohmann::json::array();
    for (const auto& p : canvas_.pins_on_screen())
      j["pins"].push_back({{"node", p.port.node}, {"port", p.port.port}, {"output", p.is_output}, {"x", p.pos.x}, {"y", p.pos.y}});
    j["node_timings"] = nlohmann::json::object();
    for (const auto& t : canvas_.timings_on_screen())
      j["node_timings"][std::to_string(t.node)] = {{"outcome", to_string(t.outcome)}, {"ms", t.ms},
                                                    {"rect", {t.rect.min.x, t.rect.min.y, t.rect.max.x - t.rect.min.x, t.rect.max.y - t.rect.min.y}}};
    j["buttons"] = buttons_;
    for (const auto& [name, r] : shape_editor_.buttons()) j["buttons"][name] = r;
    for (const auto& [name, r] : recipe_panel_.widgets()) j["buttons"][name] = r;
    for (std::size_t i = 0; i < canvas_.crumbs_on_screen().size(); ++i) {
      const Rect& r = canvas_.crumbs_on_screen()[i];
      j["buttons"]["crumb_" + std::to_string(i)] = {r.min.x, r.min.y, r.max.x - r.min.x, r.max.y - r.min.y};
    }
    j["anchor_tool"] = shape_editor_.anchor_tool();
    j["links"] = nlohmann::json::array();
    for (const auto& [to, from] : doc_->graph().links()) j["links"].push_back({from.node, from.port, to.node, to.port});
    j["params"] = nlohmann::json::object();
    for (const auto& [name, r] : inspector_.widgets()) j["params"][name] = r;
    const PreviewMesh* shown_mesh = on_screen();
    j["preview_faces"] = shown_mesh ? shown_mesh->faces : 0;
    j["viewing"] = viewed_ ? viewed_->file.string() : "";
    const std::optional<GlbLoader::Progress> loading = glb_loader_.progress();
    j["loading"] = loading ? glb_progress_text(*loading) : "";
    j["preview_anchors"] = shown_mesh ? shown_mesh->anchors.size() - shown_mesh->absent_anchors() : 0;  // present ones, with markers
    j["preview_instances"] = shown_mesh ? shown_mesh->instances : 0;
    if (shown_mesh && !shown_mesh->empty())
      j["preview_bounds"] = {shown_mesh->min.x, shown_mesh->min.y, shown_mesh->min.z, shown_mesh->max.x, shown_mesh->max.y, shown_mesh->max.z};
    j["preview"] = {preview_->image_x, preview_->image_y, preview_->image_w, preview_->image_h};
    // Images of the 3D preview shown so far. They are drawn on a thread of their own, so the image of a
    // new mesh is shown some frames after the frame that received the mesh (ui/preview_renderer.h).
    j["preview_images"] = preview_->renders();
    std::size_t errors = 0;
    if (shown_)
      for (const Diagnostic& d : shown_->result.diagnostics) errors += d.severity == Severity::kError;
    j["errors"] = errors;
    j["status"] = status_;
    j["preview_footprint"] = preview_footprint_source_;
    j["preview_features"] = shown_ ? shown_->features : 0;
    if (prompt_.kind != PathPrompt::Kind::kNone) j["prompt"] = {{"path", prompt_.path}, {"crs", export_options_.crs}, {"up_z", export_options_.up == UpAxis::Z}};
    std::string text = j.dump();
    if (text == ui_map_text_) return;
    try {
      write_file_atomically(options_.ui_map, text + "\n");
      ui_map_text_ = std::move(text);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "procex-studio: %s\n", e.what());
    }
  }

  void update_title() {
    // dirty() serialises the whole recipe once per revision: while edits stream in (a drag, a
    // 320-node street) the title's mark catches up every quarter second instead of costing every frame.
    if (doc_->revision() != title_revision_ && (!doc_->dirty_known() && Clock::now() - title_checked_ < std::chrono::milliseconds(250))) return;
    title_revision_ = doc_->revision();
    title_checked_ = Clock::now();
    std::string t = doc_->title() + (doc_->dirty() ? " *" : "") + " - procex-studio";
    if (t != title_) {
      title_ = t;
      glfwSetWindowTitle(window_, title_.c_str());
    }
  }

  GLFWwindow* window_;
  Options options_;
  fs::path home_;
  RecentFiles recent_;
  std::unique_ptr<Document> doc_;
  EvalWorker worker_{[] { glfwPostEmptyEvent(); }};  // a finished evaluation wakes the event loop
  std::string preview_footprint_source_;  // the footprint file (and its feature when it has one), or empty for the stand-in
  PreviewFeatures preview_features_;      // its features, bound to the recipe one by one; null: the stand-in
  std::shared_ptr<const GeoJsonCollection> footprints_;  // as read, without the edge labels preview_features_ has
  std::optional<EdgeLabelsRead> labelled_for_;           // the labels preview_features_ has
  ExportOptions export_options_;                   // kept between exports, as the format
  std::string export_extension_ = ".glb";
  std::shared_ptr<const EvalSnapshot> shown_;
  // shown_ as the graph being edited sees it (inside_group), and what it was made from.
  std::shared_ptr<const EvalSnapshot> here_;
  std::pair<std::shared_ptr<const EvalSnapshot>, std::vector<NodeId>> here_of_;
  struct ViewedGlb {
    fs::path file;
    std::shared_ptr<const PreviewMesh> mesh;
    std::uint64_t revision = 0;  // the recipe's when it was opened
  };
  std::optional<ViewedGlb> viewed_;
  GlbLoader glb_loader_;
  std::uint64_t submitted_ = 0, autosaved_ = 0;
  NodeId submitted_node_ = 0;
  ShapeEditor shape_editor_;
  std::unique_ptr<PreviewView> preview_;
  NodeCanvas canvas_;
  Inspector inspector_;
  RecipePanel recipe_panel_;
  LayoutSettings layout_{layout_settings_path()};
  const bool interactive_;  // a person's session: no screenshot or benchmark
  bool keep_layout_ = false;
  std::string status_, title_, ui_map_text_;
  std::vector<float> last_placements_;  // the last frame's panels (layout_windows)
  bool layout_moving_ = true;
  std::uint64_t title_revision_ = 0;
  Clock::time_point title_checked_;
  WidgetRects buttons_;
  PathPrompt prompt_;
  std::optional<fs::path> recovery_;
  std::function<void()> pending_;
  bool confirm_requested_ = false, quit_ = false, load_failed_ = false;
  bool canvas_has_keys_ = false;  // the node canvas has the keyboard (its shortcuts work)
  Clock::time_point last_autosave_ = Clock::now();
};

namespace {

// What a screenshot shows, for tests that check the image.
void write_screenshot_info(const fs::path& file, App& app, int width, int height) {
  nlohmann::json j;
  j["width"] = width;
  j["height"] = height;
  const PreviewView& p = app.preview();
  j["preview"] = {{"x", p.image_x}, {"y", p.image_y}, {"w", p.image_w}, {"h", p.image_h}};
  j["tags"] = nlohmann::json::array();
  std::size_t errors = 0;
  if (const EvalSnapshot* s = app.shown())
    for (const Diagnostic& d : s->result.diagnostics) errors += d.severity == Severity::kError;
  const PreviewMesh* shown = app.on_screen();
  if (shown)
    for (const TagSummary& t : shown->tags) {
      j["tags"].push_back({{"name", t.name}, {"color", {t.color.r, t.color.g, t.color.b}}, {"faces", t.faces}, {"area", t.area}, {"area_up", t.area_up}});
      // A textured tag shows its texture's colours (times its own), not one colour.
      if (t.texture >= 0)
        for (const glm::vec3& c : shown->textures.at(static_cast<std::size_t>(t.texture)).palette)
          j["tags"].back()["texture_colours"].push_back({c.r, c.g, c.b});
    }
  j["errors"] = errors;
  // How readable the node canvas is: its zoom and the smallest text it drew.
  j["canvas"] = {{"zoom", app.canvas().zoom()}, {"min_text_px", app.canvas().min_text_px()}, {"legible_zoom", NodeCanvas::legible_zoom()}};
  const glm::vec3 marker = PreviewMesh::kAnchorColor;
  j["anchor_color"] = {marker.r, marker.g, marker.b};
  j["anchors_present"] = shown ? shown->anchors.size() - shown->absent_anchors() : 0;
  j["instances"] = shown ? shown->instances : 0;
  write_file_atomically(file, j.dump(2) + "\n");
}

// Parameter edits timed until their result is on screen (the benchmark mode).
class EditBench {
 public:
  explicit EditBench(int edits) : edits_(edits) {}
  bool done() const { return done_ >= edits_; }
  // Call once per frame after the swap.
  void step(App& app) {
    if (waiting_ && app.settled()) {
      latencies_.push_back(ms_since(edit_time_));
      evaluation_ms_.push_back(app.shown()->seconds * 1e3);
      waiting_ = false;
      ++done_;
    }
    if (waiting_ || done() || !app.settled()) return;
    // The first float parameter with a range, of the recipe's nodes or else inside its first group
    // (entered as a person would: an edit there changes every instance). Each edit a new value, so
    // nothing comes from the cache.
    const auto ranged = [](const Graph& g) -> std::optional<std::pair<NodeId, std::size_t>> {
      for (const auto& [id, n] : g.nodes())
        for (std::size_t i = 0; i < n.params.size(); ++i)
          if (const ParamDecl& p = n.decl().params()[i]; n.params[i].is<double>() && p.min && p.max) return std::pair(id, i);
      return std::nullopt;
    };
    std::optional<std::pair<NodeId, std::size_t>> found = ranged(app.doc().graph());
    if (!found && app.doc().scope().empty())
      for (const auto& [id, n] : app.doc().graph().nodes())
        if (!n.group.empty() && app.doc().enter_group(id)) {
          found = ranged(app.doc().graph());
          break;
        }
    if (!found) {
      done_ = edits_;  // nothing to edit
      return;
    }
    const auto [id, i] = *found;
    const ParamDecl& p = app.doc().graph().node(id)->decl().params()[i];
    const double v = *p.min + (*p.max - *p.min) * (0.3 + 0.4 * (done_ + 1) / (edits_ + 1));
    edit_time_ = Clock::now();
    waiting_ = true;
    const std::vector<std::string> crumbs = app.doc().breadcrumb();
    param_.clear();
    for (std::size_t c = 1; c < crumbs.size(); ++c) param_ += crumbs[c] + " > ";  // the groups entered
    param_ += app.doc().graph().node(id)->decl().type_name() + "." + p.name;
    if (Status s = app.doc().set_param(id, i, Value::make(v)); !s) std::fprintf(stderr, "procex-studio: bench edit refused: %s\n", s.message().c_str());
  }
  nlohmann::json report() const { return {{"parameter", param_}, {"edit_to_screen_ms", latencies_}, {"evaluation_ms", evaluation_ms_}}; }

 private:
  int edits_, done_ = 0;
  bool waiting_ = false;
  Clock::time_point edit_time_;
  std::vector<double> latencies_, evaluation_ms_;
  std::string param_;
};

}  // namespace

int run_studio(const Options& options) {
  if (!glfwInit()) {
    std::fprintf(stderr, "procex-studio: cannot initialise GLFW (is DISPLAY set? under CI use xvfb-run)\n");
    return 1;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  GLFWwindow* window = glfwCreateWindow(options.width, options.height, "procex-studio", nullptr, nullptr);
  if (!window) {
    std::fprintf(stderr, "procex-studio: cannot open a window with OpenGL 3.3\n");
    glfwTerminate();
    return 1;
  }
  glfwMakeContextCurrent(window);
  const bool automated = !options.screenshot.empty() || options.bench_edits > 0;
  glfwSwapInterval(automated ? 0 : 1);
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini in the working folder: LayoutSettings keeps it per user
  ImGui::StyleColorsDark();
  InputQueue input;  // mouse and keyboard, in one order
  auto mouse = std::make_unique<MouseInput>(window, input);  // first: ImGui's backend chains its button callback after it
  auto keys = std::make_unique<KeyInput>(window, input);     // so too its key and character callbacks
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");

  int exit_code = 0;
  {
    App app(window, options);
    EditBench bench(options.bench_edits);
    std::vector<double> frame_ms, busy_frame_ms, build_ms, draw_ms, redrawn_share, frame_cpu_ms, rasteriser_cpu_ms, preview_thread_cpu_ms;
    std::vector<int> preview_shown, preview_drawing;
    PartialRedraw redraw(copy_sub_buffer_available());
    std::uint64_t preview_renders = 0;
    // Uncovered or resized by the window system: its pixels are redrawn in full.
    // Files dropped: opened by the app in the next frame.
    struct WindowEvents {
      bool exposed = true;
      std::vector<fs::path> dropped;
    } events;
    glfwSetWindowUserPointer(window, &events);
    glfwSetWindowRefreshCallback(window, [](GLFWwindow* w) { static_cast<WindowEvents*>(glfwGetWindowUserPointer(w))->exposed = true; });
    glfwSetDropCallback(window, [](GLFWwindow* w, int count, const char** paths) {
      for (int i = 0; i < count; ++i) static_cast<WindowEvents*>(glfwGetWindowUserPointer(w))->dropped.emplace_back(paths[i]);
    });
    const auto start = Clock::now();
    double load_at_start[3] = {0, 0, 0};
    if (getloadavg(load_at_start, 3) < 0) load_at_start[0] = -1;
    int settled_frames = 0;
    while (exit_code == 0) {
      if (automated && app.load_failed()) {  // a recipe, or (once read) a .glb, that does not load
        exit_code = 1;
        break;
      }
      const auto frame_start = Clock::now();
      const double frame_start_cpu = thread_cpu_ms();
      // Benchmark only: reading every thread's counters costs a few system calls. The rasteriser's
      // threads are shared with the preview's context (ui/preview_renderer.h): a frame during which
      // the preview's thread drew counts that image's filling too, and is marked (preview_drawing).
      const double raster_start_cpu = options.bench_edits > 0 ? threads_cpu_ms("llvmpipe-") : 0.0;
      const bool preview_drawing_at_start = app.preview_drawing();
      const double preview_thread_start_cpu = app.preview_render_cpu_ms();
      const std::uint64_t preview_images_at_start = app.preview_images();
      // Mouse or key changes queued, or panels moved in the last frame: show the next at once.
      // Otherwise wait for an event: a finished evaluation posts one (EvalWorker's `finished`), so
      // its result shows at once and nothing polls the worker meanwhile, taking a core from it.
      // Automated runs (screenshots, benchmarks) go on without waiting once nothing is evaluating.
      // So do they while an image of the preview is being drawn: its thread posts an event when it is finished.
      if (input.pending() || app.layout_moving() || (automated && !app.busy() && !app.preview_pending())) glfwPollEvents();
      else glfwWaitEventsTimeout(app.loading_glb() ? 0.01 : 0.25);  // a .glb's progress shows as it loads
      if (glfwWindowShouldClose(window)) app.request_quit();
      if (app.quit()) break;
      for (const fs::path& f : events.dropped) app.open_dropped(f);
      events.dropped.clear();
      const bool busy = app.busy();
      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      const InputQueue::Frame changed = input.next();
      MouseInput::before_new_frame(changed);
      KeyInput::before_new_frame(changed);
      ImGui::NewFrame();
      MouseInput::after_new_frame(changed);
      const auto build_start = Clock::now();
      app.frame();
      ImGui::Render();
      build_ms.push_back(ms_since(build_start));
      int w = 0, h = 0;
      glfwGetFramebufferSize(window, &w, &h);
      // Windows settle during their first frames: a screenshot waits for a few frames of the final result.
      settled_frames = app.settled() ? settled_frames + 1 : 0;
      const bool timed_out = std::chrono::duration<double>(Clock::now() - start).count() > options.timeout_s;
      // With --bench-edits too: the picture after the last edit.
      const bool shoot = !options.screenshot.empty() && ((settled_frames >= 3 && bench.done()) || timed_out);
      std::vector<std::uintptr_t> redrawn;
      if (app.preview().renders() != preview_renders) redrawn.push_back(app.preview().texture());
      preview_shown.push_back(app.preview().renders() != preview_renders);
      preview_renders = app.preview().renders();
      if (events.exposed || options.full_redraw) redraw.invalidate();  // uncovered by the window system: everything is drawn again
      events.exposed = false;
      const PartialRedraw::Outcome drawn = redraw.render(ImGui::GetDrawData(), w, h, back_buffer_age(), redrawn, shoot);
      if (options.bench_edits > 0) {
        glFinish();  // benchmark: the software rasteriser's share, apart from the swap
        draw_ms.push_back(ms_since(build_start) - build_ms.back());
        redrawn_share.push_back(drawn.pixels_redrawn / (static_cast<double>(w) * h));
      }
      if (!options.screenshot.empty()) {
        if (shoot) {
          try {
            save_back_buffer_png(w, h, options.screenshot);
            if (!options.screenshot_info.empty()) write_screenshot_info(options.screenshot_info, app, w, h);
          } catch (const std::exception& e) {
            std::fprintf(stderr, "procex-studio: %s\n", e.what());
            exit_code = 1;
          }
          if (timed_out) {
            std::fprintf(stderr, "procex-studio: the evaluation did not finish within %g s\n", options.timeout_s);
            exit_code = 2;
          }
          break;
        }
      }
      // Otherwise the window already shows this frame.
      if (drawn.presented) glfwSwapBuffers(window);
      else if (!drawn.copy_to_window.empty()) copy_sub_buffer(drawn.copy_to_window, h);
      if (options.bench_edits > 0) {
        glFinish();
        bench.step(app);
      }
      const double ms = ms_since(frame_start);
      frame_ms.push_back(ms);
      frame_cpu_ms.push_back(thread_cpu_ms() - frame_start_cpu);
      preview_drawing.push_back(preview_drawing_at_start || app.preview_drawing() || app.preview_images() != preview_images_at_start);
      preview_thread_cpu_ms.push_back(app.preview_render_cpu_ms() - preview_thread_start_cpu);
      if (options.bench_edits > 0) rasteriser_cpu_ms.push_back(threads_cpu_ms("llvmpipe-") - raster_start_cpu);
      if (busy) busy_frame_ms.push_back(ms);
      if (options.bench_edits > 0 && options.screenshot.empty() && (bench.done() || std::chrono::duration<double>(Clock::now() - start).count() > options.timeout_s))
        break;
    }
    if (!options.frame_report.empty()) {
      nlohmann::json j = bench.report();
      j["preview_features"] = app.shown() ? app.shown()->features : 0;  // buildings of a footprint file (--footprints)
      j["frame_ms"] = frame_ms;
      j["frame_ms_while_evaluating"] = busy_frame_ms;
      j["ui_build_ms"] = build_ms;
      j["draw_ms"] = draw_ms;
      j["redrawn_share"] = redrawn_share;
      // The UI thread's CPU time per frame, and what every thread used in the whole run: the
      // UI thread, the evaluation's (procex-eval) and the software rasteriser's (llvmpipe-N).
      j["frame_cpu_ms"] = frame_cpu_ms;
      j["rasteriser_cpu_ms"] = rasteriser_cpu_ms;  // the llvmpipe threads, per frame
      // The frames that showed a new image of the 3D preview; those during which its thread drew
      // (their rasteriser CPU time counts that image's filling too); the CPU time its thread
      // (procex-preview) used in each frame's time, counted when an image is finished: uploading
      // meshes and issuing the drawing.
      j["preview_shown"] = preview_shown;
      j["preview_drawing"] = preview_drawing;
      j["preview_thread_cpu_ms"] = preview_thread_cpu_ms;
      for (const ThreadCpu& t : threads_cpu()) j["threads"][t.name] = {{"cpu_ms", t.cpu_ms}, {"waiting_ms", t.waiting_ms}};
      j["presented_by"] = copy_sub_buffer_available() ? "copy_sub_buffer" : "swap";
      double load_at_end[3] = {0, 0, 0};
      if (getloadavg(load_at_end, 3) < 0) load_at_end[0] = -1;
      j["load_average"] = {load_at_start[0], load_at_end[0]};
      try {
        write_file_atomically(options.frame_report, j.dump() + "\n");
      } catch (const std::exception& e) {
        std::fprintf(stderr, "procex-studio: %s\n", e.what());
      }
    }
    if (!automated) app.leave();
    if (!app.stop_evaluation(std::chrono::seconds(3))) {
      // Joining the evaluation thread would hang the exit: everything worth keeping is written.
      std::fprintf(stderr, "procex-studio: an evaluation does not stop; exiting without waiting for it\n");
      std::fflush(nullptr);
      std::_Exit(exit_code);
    }
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  mouse.reset();
  keys.reset();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
  return exit_code;
}

}  // namespace procex::studio

// render_report.cpp — measures the renderer: specialised against uber, cost against object
// count, marching error and aliasing against frame time, and the quality presets. All numbers
// come from one run.
#include "marchbox/report/render_report.h"

#include "device_report.h"
#include "report_plot.h"
#include "report_template.h"
#include "sequence_report.h"

#include "marchbox/gl/offscreen_context.h"
#include "marchbox/gl/quality_preset.h"
#include "marchbox/gl/renderer.h"
#include "marchbox/report/physics_scenes.h"
#include "marchbox/scene/scene_io.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <sstream>

namespace mb {

namespace {

constexpr int kWidth = 480, kHeight = 270;  // the size draft's bar is set at
constexpr int kFrames = 9;  // a median of 5 still moved a row by a third when the machine stirred
// Draft's bar on every example scene: this much faster than the scene as written, at this PSNR.
constexpr double kDraftSpeedUp = 2.0, kDraftDb = 28.0;

double drawMs(Renderer& r, int w, int h) {
    auto t0 = std::chrono::steady_clock::now();
    r.draw(w, h);
    glFinish();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// The fastest of kFrames frames after a warm-up frame: other work on the machine only ever
// adds time. A frame slower than a second is timed once. Negative when it cannot be drawn.
double frameMs(Renderer& r, const Scene& scene, const RenderOptions& o, int w = kWidth,
               int h = kHeight) {
    std::string error;
    if (!r.setScene(scene, o, &error)) return -1;
    double best = drawMs(r, w, h);
    if (best > 1000) return drawMs(r, w, h);
    for (int i = 0; i < kFrames; ++i) best = std::min(best, drawMs(r, w, h));
    return best;
}

RenderOptions specialised(int grid = -1) {
    RenderOptions o;
    o.quality.grid = grid;
    return o;
}

RenderOptions uber() {
    RenderOptions o;
    o.uber = true;
    return o;
}

// An example scene; one that does not load leaves its rows out of the report.
bool loadExample(const std::filesystem::path& file, Scene* scene) {
    std::vector<std::string> errors;
    return loadScene(file.string(), scene, &errors);
}
bool loadExample(const std::string& root, const std::string& name,
                 Scene* scene) {  // scenes/NAME.txt
    return loadExample(root + "/scenes/" + name + ".txt", scene);
}

std::string uberTable(Renderer& r, const std::string& root) {
    std::ostringstream md;
    md << "| scene | objects | specialised ms | uber ms | uber / specialised | mean diff /255 |\n"
          "| --- | ---: | ---: | ---: | ---: | ---: |\n";
    auto row = [&](const std::string& name, const Scene& s) {
        double spec = frameMs(r, s, specialised());
        Image specImage = readFramebuffer(kWidth, kHeight);
        double ub = frameMs(r, s, uber());
        double diff = diffImages(specImage, readFramebuffer(kWidth, kHeight)).meanAbs;
        md << "| " << name << " | " << s.objects.size() << " | " << fmt("%.1f", spec) << " | "
           << fmt("%.1f", ub) << " | " << fmt("%.2f", ub / spec) << " | " << fmt("%.2f", diff)
           << " |\n";
    };
    for (const auto& path : exampleSceneFiles(root)) {
        Scene s;
        if (!loadExample(path, &s)) continue;
        row(path.stem().string(), s);
        if (path.stem() != "primitives") continue;
        s.render.shadows = 0;  // the case with the least to switch: no mirrors, no shadows
        row("primitives, no shadows, no mirrors", s);
    }
    return md.str();
}

// n spheres on a square lattice 1 m apart under one light, seen from above at an angle.
Scene sphereField(int n) {
    Scene s;
    s.materials.push_back({});
    s.lights.push_back(Light{false, {4, 12, -8}, {1, 1, 1}, 1});
    s.render.reflections = 0;
    int side = int(std::ceil(std::sqrt(double(n))));
    for (int i = 0; i < n; ++i) {
        Object o;
        o.pos = {float(i % side) - 0.5f * side, 0.35f, float(i / side) - 0.5f * side};
        o.radius = 0.35f;
        s.objects.push_back(o);
    }
    s.camera.pos = {0, 0.9f * side + 3, -1.1f * side - 4};
    s.camera.target = {0, 0, 0};
    return s;
}

// The targets for many bodies, from this run: n spheres against 10, each as the renderer draws it
// (straight-line code or the grid, as usesGrid chooses), and the example pile against the
// default scene.
std::string scalingTargets(Renderer& r, const std::string& root,
                           const std::map<int, double>& drawn) {
    Scene pile, start;
    if (!loadExample(root, "pile", &pile) || !loadExample(root, "default", &start)) return "";
    const double pileMs = frameMs(r, pile, specialised()),
                 startMs = frameMs(r, start, specialised());
    const double mixedMs = frameMs(r, mixedPileScene(1000, 7), specialised());
    char text[512];
    std::snprintf(text, sizeof text,
                  "\n1,000 spheres cost **%.2fx** what 10 do (target <= 3x, goal 2x), 4,096 "
                  "**%.2fx** (target <= 4x). `pile.txt` costs **%.2fx** `default.txt` (target <= "
                  "2.5x): %.1f against %.1f ms. A mixed pile of 1,000 boxes, capsules, cylinders "
                  "and spheres, each turned, draws in %.1f ms.\n",
                  drawn.at(1000) / drawn.at(10), drawn.at(4096) / drawn.at(10), pileMs / startMs,
                  pileMs, startMs, mixedMs);
    return text;
}

std::string scalingTable(Renderer& r, const std::string& root, const std::string& docs) {
    std::ostringstream md;
    md << "| spheres | uber ms | specialised, no grid ms | specialised + grid ms |\n"
          "| ---: | ---: | ---: | ---: |\n";
    PlotSeries seriesUber{"uber", {}, true, {}}, seriesFlat{"specialised", {}, true, {}},
        seriesGrid{"specialised + grid", {}, true, {}};
    // A variant past 20 s a frame is not timed at larger counts: it only gets slower.
    double lastFlat = 0;
    std::map<int, double> drawnMs;
    for (int n : {1, 10, 32, 64, 100, 1000, 4096}) {
        Scene s = sphereField(n);
        double ub = frameMs(r, s, uber()), grid = frameMs(r, s, specialised(1));
        double flat = lastFlat > 20000 ? -2 : frameMs(r, s, specialised(0));
        lastFlat = flat;
        auto cell = [](double v) {
            return v == -2 ? std::string("> 20 s") : v < 0 ? std::string("n/a") : fmt("%.1f", v);
        };
        md << "| " << n << " | " << cell(ub) << " | " << cell(flat) << " | " << cell(grid)
           << " |\n";
        if (ub > 0) seriesUber.points.emplace_back(n, ub);
        if (flat > 0) seriesFlat.points.emplace_back(n, flat);
        seriesGrid.points.emplace_back(n, grid);
        drawnMs[n] = usesGrid(s, RenderQuality{}) || flat <= 0 ? grid : flat;
    }
    writeTextFile(docs + "/render-scaling.svg",
                  logLogPlotSvg("Frame time against sphere count (480x270)", "spheres",
                                "frame time (ms)", {seriesUber, seriesFlat, seriesGrid}));
    return md.str() + scalingTargets(r, root, drawnMs);
}

// ---------------------------------------------------------------------------------------------
// Work precision. Marching error and aliasing are measured apart: a marching setting is compared
// with the converged render at the same sampling, and supersampling with a supersampled
// reference at the same marching. Times are medians of kFrames frames, the frames of every
// setting in a sweep interleaved, so that a burst of other work on the machine lands on all of
// them alike; the spread is the fastest and the slowest frame.

constexpr int kAliasWidth = 240, kAliasHeight = 135;  // the aliasing sweep draws up to 8x8 samples
// The aliasing reference: aa 4 drawn at twice the size and box-filtered down, 8x8 samples a pixel.
constexpr int kAliasReferenceAa = 4, kAliasReferenceScale = 2;

struct Timing {
    double median = 0, min = 0, max = 0;
};

struct Variant {  // one setting of one scene, ready to draw
    std::string sweep, label;
    Scene scene;
    RenderOptions options;
};

struct Result {
    Variant variant;
    Timing time;
    double error = 0;  // RMSE against the reference, 0..255
};

// Draws every variant once (compiling, warming up, and keeping the image), then kFrames rounds
// in which each variant draws one timed frame in turn.
std::vector<Result> measure(Renderer& r, const std::vector<Variant>& variants,
                            const Image& reference, int w, int h) {
    std::vector<Result> out;
    std::vector<std::vector<double>> ms(variants.size());
    std::string error;
    for (const Variant& v : variants) {
        Result res{v, {}, -1};
        if (r.setScene(v.scene, v.options, &error)) {
            r.draw(w, h);
            res.error = rmse(readFramebuffer(w, h), reference);
        }
        out.push_back(res);
    }
    for (int round = 0; round < kFrames; ++round)
        for (size_t i = 0; i < variants.size(); ++i)
            if (out[i].error >= 0 && r.setScene(variants[i].scene, variants[i].options, &error))
                ms[i].push_back(drawMs(r, w, h));
    for (size_t i = 0; i < out.size(); ++i) {
        std::vector<double>& t = ms[i];
        if (t.empty()) continue;
        std::sort(t.begin(), t.end());
        out[i].time = {t[t.size() / 2], t.front(), t.back()};
    }
    return out;
}

Image renderImage(Renderer& r, const Scene& scene, const RenderOptions& o, int w, int h) {
    std::string error;
    if (!r.setScene(scene, o, &error)) return makeImage(w, h);
    r.draw(w, h);
    return readFramebuffer(w, h);
}

// An RMSE as PSNR for a table: "inf" for a picture identical to its reference.
std::string dB(double rmse) { return fmt("%.1f", psnrFromRmse(rmse)); }

// On the front when every other setting at least as accurate (within 0.1 dB, below which
// PSNR differences are single pixels) is slower by more than the spread: its fastest frame is
// slower than this setting's slowest.
bool onFront(const Result& a, const std::vector<Result>& all) {
    for (const Result& b : all) {
        if (&a == &b || b.error < 0) continue;
        bool asAccurate = psnrFromRmse(b.error) >= psnrFromRmse(a.error) - 0.1;
        if (asAccurate && b.time.min <= a.time.max) return false;
    }
    return a.error >= 0;
}

std::string timeCells(const Timing& t) {
    return fmt("%.1f", t.median) + " | " + fmt("%.1f", t.min) + "–" + fmt("%.1f", t.max);
}

std::string resultTable(const std::vector<Result>& all, const Result* baseline) {
    std::ostringstream md;
    md << "| sweep | setting | median ms | min–max ms | speed-up | PSNR dB | Pareto |\n"
          "| --- | --- | ---: | ---: | ---: | ---: | :---: |\n";
    for (const Result& m : all)
        md << "| " << m.variant.sweep << " | " << m.variant.label << " | " << timeCells(m.time)
           << " | "
           << (baseline ? fmt("%.2fx", baseline->time.median / m.time.median) : std::string(""))
           << " | " << dB(m.error) << " | " << (onFront(m, all) ? "yes" : "") << " |\n";
    return md.str();
}

void plotResults(const std::string& path, const std::string& title,
                 const std::vector<Result>& all) {
    PlotSeries points{"settings", {}, false, {}}, front{"Pareto front", {}, true, {}};
    std::vector<const Result*> sorted;
    for (const Result& m : all) {
        points.points.emplace_back(m.time.median, m.error);
        points.xSpread.emplace_back(m.time.min, m.time.max);
        if (onFront(m, all)) sorted.push_back(&m);
    }
    std::sort(sorted.begin(), sorted.end(),
              [](auto* a, auto* b) { return a->time.median < b->time.median; });
    for (const Result* m : sorted) front.points.emplace_back(m->time.median, m->error);
    writeTextFile(path, logLogPlotSvg(title, "frame time (ms), median with min–max whiskers",
                                      "RMSE against reference (0-255)", {points, front}));
}

// The marching sweeps: each row changes one setting of the scene as written, then the presets.
std::vector<Variant> marchingVariants(const Scene& scene) {
    std::vector<Variant> out;
    auto add = [&](const std::string& sweep, const std::string& label, auto change) {
        Variant v{sweep, label, scene, {}};
        change(v.scene.render, v.options.quality);
        out.push_back(v);
    };
    const RenderSettings& r = scene.render;
    add("as written", "steps " + std::to_string(r.steps) + ", epsilon " + fmt("%g", r.epsilon),
        [](auto&, auto&) {});
    for (int steps : {32, 64, 128, 512})
        if (steps != r.steps)
            add("steps", std::to_string(steps), [=](RenderSettings& s, auto&) { s.steps = steps; });
    for (float eps : {1e-2f, 3e-3f, 1e-4f})
        add("epsilon", fmt("%g", eps), [=](RenderSettings& s, auto&) { s.epsilon = eps; });
    for (int relax : {120, 150})
        add("relaxation", fmt("%.2f", relax / 100.0),
            [=](auto&, RenderQuality& q) { q.relaxPercent = relax; });
    if (r.shadows)
        for (int shadow : {16, 32, 64, 256})
            add("shadow steps", std::to_string(shadow),
                [=](auto&, RenderQuality& q) { q.shadowSteps = shadow; });
    add("cone epsilon", "on", [](auto&, RenderQuality& q) { q.coneEpsilon = true; });
    if (r.shadows && scene.lights.size() > 1)
        add("shadow casters", "lights >= 0.5 of the brightest",
            [](auto&, RenderQuality& q) { q.shadowCutoff = 0.5f; });
    if (r.shadows) add("shadows", "none", [](RenderSettings& s, auto&) { s.shadows = 0; });
    for (int refl = 0; refl < std::min(r.reflections, 2); ++refl)
        add("reflections", std::to_string(refl),
            [=](RenderSettings& s, auto&) { s.reflections = refl; });
    add("pixels shaded", "half, checkerboard",
        [](auto&, RenderQuality& q) { q.checkerboard = true; });
    for (QualityPreset p : {QualityPreset::Draft, QualityPreset::Final}) {
        Variant v{"preset", std::string(qualityPresetName(p)) + " (marching only)", scene, {}};
        applyQualityPreset(p, &v.scene.render, &v.options);
        v.scene.render.aa = scene.render.aa;     // sampling belongs to the aliasing sweep
        v.options.quality.checkerboard = false;  // and pixels to their own row
        out.push_back(v);
    }
    return out;
}

// Where a frame's time goes: the debug views draw the primary march alone (id) and with the
// normal (normals); each other column leaves one part out. Times only: no picture is judged.
std::string costSection(Renderer& r, const std::vector<std::string>& names,
                        const std::string& root) {
    std::ostringstream md;
    md << "| scene | as written ms | primary march only (id view) | + normal (normals view) | no "
          "shadows | "
          "no reflections | no shadows, no reflections |\n| --- | ---: | ---: | ---: | ---: | ---: "
          "| ---: |\n";
    for (const std::string& name : names) {
        std::cerr << "render report: cost, " << name << '\n';
        Scene scene;
        if (!loadExample(root, name, &scene)) continue;
        std::vector<Variant> v(6, Variant{"", "", scene, {}});
        v[1].options.mode = RenderMode::ObjectId;
        v[2].options.mode = RenderMode::Normals;
        v[3].scene.render.shadows = v[5].scene.render.shadows = 0;
        v[4].scene.render.reflections = v[5].scene.render.reflections = 0;
        std::vector<Result> all = measure(r, v, makeImage(kWidth, kHeight), kWidth, kHeight);
        md << "| " << name << " | " << fmt("%.1f", all[0].time.median);
        for (size_t i = 1; i < all.size(); ++i)
            md << " | " << fmt("%.1f", all[i].time.median) << " ("
               << fmt("%.0f%%", 100 * all[i].time.median / all[0].time.median) << ")";
        md << " |\n";
    }
    return md.str();
}

std::string marchingSection(Renderer& r, const std::string& name, const Scene& scene,
                            const std::string& docs, std::string* verdict) {
    std::cerr << "render report: marching, " << name << '\n';
    Image reference = renderImage(r, converged(scene), {}, kWidth, kHeight);
    std::vector<Result> all = measure(r, marchingVariants(scene), reference, kWidth, kHeight);
    const std::string svg = "render-precision-" + name + ".svg";
    plotResults(docs + "/" + svg,
                "Marching error against frame time, " + name + ".txt (" + std::to_string(kWidth) +
                    "x" + std::to_string(kHeight) + ")",
                all);
    const Result& asWritten = all.front();
    const Result* draft = nullptr;
    for (const Result& m : all)
        if (m.variant.label.rfind("draft", 0) == 0) draft = &m;
    *verdict = "| " + name + " | " + dB(asWritten.error) + " | " +
               fmt("%.2fx", asWritten.time.median / draft->time.median) + " | " + dB(draft->error) +
               " |\n";
    return "### " + name + "\n\n![" + name + "](" + svg + ")\n\n" + resultTable(all, &asWritten);
}

std::string aliasingSection(Renderer& r, const std::string& name, const Scene& scene) {
    std::cerr << "render report: aliasing, " << name << '\n';
    const int w = kAliasWidth, h = kAliasHeight;
    Scene ref = scene;
    ref.render.aa = kAliasReferenceAa;
    const int n = kAliasReferenceScale;
    Image reference = boxDownsample(renderImage(r, ref, {}, n * w, n * h), n);
    std::vector<Variant> variants;
    for (int aa = 1; aa <= 4; ++aa) {
        Variant v{"aa", std::to_string(aa) + "x" + std::to_string(aa), scene, {}};
        v.scene.render.aa = aa;
        variants.push_back(v);
        if (aa > 2) continue;
        v.label += " + FXAA";
        v.options.post = PostMode::Fxaa;
        variants.push_back(v);
    }
    std::vector<Result> all = measure(r, variants, reference, w, h);
    return "### " + name + "\n\n" + resultTable(all, &all.front());
}

// Example scenes, each as written against draft, normal and final, all three
// against one reference: converged marching at 4x4 supersampling.
std::string presetSection(Renderer& r, const std::vector<std::string>& names,
                          const std::string& root) {
    std::ostringstream md;
    md << "| scene | preset | median ms | min–max ms | speed-up | PSNR dB against converged, same "
          "aa | "
          "PSNR dB against converged 4x4 |\n| --- | --- | ---: | ---: | ---: | ---: | ---: |\n";
    for (const std::string& name : names) {
        std::cerr << "render report: presets, " << name << '\n';
        Scene scene;
        if (!loadExample(root, name, &scene)) continue;
        Scene ref4 = converged(scene);
        ref4.render.aa = 4;
        Image reference4 = renderImage(r, ref4, {}, kWidth, kHeight);
        std::vector<Variant> variants;
        std::vector<Image> sameAa;
        for (int p = 0; p < kQualityPresetCount; ++p) {
            Variant v{"", qualityPresetName(QualityPreset(p)), scene, {}};
            applyQualityPreset(QualityPreset(p), &v.scene.render, &v.options);
            Scene c = converged(scene);
            c.render.aa = v.scene.render.aa;
            sameAa.push_back(renderImage(r, c, {}, kWidth, kHeight));
            variants.push_back(v);
        }
        std::vector<Result> all = measure(r, variants, reference4, kWidth, kHeight);
        for (size_t i = 0; i < all.size(); ++i) {
            double same = rmse(
                renderImage(r, variants[i].scene, variants[i].options, kWidth, kHeight), sameAa[i]);
            md << "| " << name << " | " << all[i].variant.label << " | " << timeCells(all[i].time)
               << " | " << fmt("%.2fx", all[1].time.median / all[i].time.median) << " | "
               << dB(same) << " | " << dB(all[i].error) << " |\n";
        }
    }
    return md.str();
}

// Draft's bar on every example scene: its frames and the scene's as written
// interleaved, its error against the scene as written converged (at the scene's own aa, so an
// aa cap counts as error).
std::string draftSection(Renderer& r, const std::string& root, int* passing, int* scenes) {
    std::ostringstream md;
    md << "| scene | as written ms | draft ms | draft min–max ms | speed-up | draft PSNR dB |\n"
          "| --- | ---: | ---: | ---: | ---: | ---: |\n";
    for (const auto& path : exampleSceneFiles(root)) {
        std::cerr << "render report: draft, " << path.stem().string() << '\n';
        Scene scene;
        if (!loadExample(path, &scene)) continue;
        Variant asWritten{"", "", scene, {}}, draft = asWritten;
        applyQualityPreset(QualityPreset::Draft, &draft.scene.render, &draft.options);
        Image reference = renderImage(r, converged(scene), {}, kWidth, kHeight);
        std::vector<Result> all = measure(r, {asWritten, draft}, reference, kWidth, kHeight);
        double speedUp = all[0].time.median / all[1].time.median, db = psnrFromRmse(all[1].error);
        *passing += speedUp >= kDraftSpeedUp && db >= kDraftDb;
        ++*scenes;
        md << "| " << path.stem().string() << " | " << fmt("%.1f", all[0].time.median) << " | "
           << timeCells(all[1].time) << " | " << fmt("%.2fx", speedUp) << " | " << fmt("%.1f", db)
           << " |\n";
    }
    return md.str();
}

std::string presetSettingsTable() {
    std::ostringstream md;
    md << "| preset | march steps | epsilon | reflections | supersampling | shadow steps | cone "
          "epsilon | "
          "shadows cast by | pixels shaded |\n| --- | --- | --- | --- | --- | --- | --- | --- | "
          "--- |\n";
    auto cap = [](const char* what, double lo, double hi, const char* fmtText) {
        if (lo > 0 && hi > 0) return std::string("as written");
        if (hi > 0) return std::string("at most ") + fmt(fmtText, hi);
        if (lo > 0) return std::string("at least ") + fmt(fmtText, lo);
        return std::string(what);
    };
    for (int p = 0; p < kQualityPresetCount; ++p) {
        const QualityPresetSettings& s = qualityPresetSettings(QualityPreset(p));
        md << "| " << s.name << " | " << cap("as written", s.minSteps, s.maxSteps, "%g") << " | "
           << cap("as written", s.minEpsilon, s.maxEpsilon, "%g") << " | "
           << (s.maxReflections >= 0 ? "at most " + std::to_string(s.maxReflections)
                                     : std::string("as written"))
           << " | " << cap("as written", s.minAa, s.maxAa, "%g")
           << (s.minAa + s.maxAa ? " per axis" : "") << " | "
           << (s.shadowSteps ? std::to_string(s.shadowSteps) : std::string("128")) << " | "
           << (s.coneEpsilon ? "on" : "off") << " | "
           << (s.shadowCutoff > 0
                   ? "lights at least " + fmt("%g", s.shadowCutoff) + " as bright as the brightest"
                   : std::string("every light"))
           << " | "
           << (s.checkerboard ? "half, in a checkerboard; the rest filled in" : "every one")
           << " |\n";
    }
    return md.str();
}

// The marching sweeps of each scene, and the summary of draft's marching against each.
void marchingSections(Renderer& r, const std::vector<std::string>& names, const std::string& root,
                      const std::string& docs, TemplateValues* v) {
    std::string sections, verdicts;
    for (const std::string& name : names) {
        Scene scene;
        if (!loadExample(root, name, &scene)) continue;
        std::string verdict;
        sections += marchingSection(r, name, scene, docs, &verdict) + "\n";
        verdicts += verdict;
    }
    (*v)["marching_sections"] = sections;
    (*v)["marching_summary"] =
        "| scene | as written dB | draft speed-up | draft dB |\n"
        "| --- | ---: | ---: | ---: |\n" +
        verdicts;
}

std::string aliasingSections(Renderer& r, const std::vector<std::string>& names,
                             const std::string& root) {
    std::string md;
    for (const std::string& name : names) {
        Scene scene;
        if (loadExample(root, name, &scene)) md += aliasingSection(r, name, scene) + "\n";
    }
    return md;
}

std::string sizeText(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

// The settings and sizes the prose names, from the constants the measurements use.
void describeMethod(TemplateValues* v) {
    const RenderSettings reference = converged(Scene{}).render;
    const int samples = kAliasReferenceAa * kAliasReferenceScale;
    (*v)["size"] = sizeText(kWidth, kHeight);
    (*v)["frames"] = std::to_string(kFrames);
    (*v)["grid_min_objects"] = std::to_string(kGridMinObjects);
    (*v)["converged"] =
        std::to_string(reference.steps) + " steps, epsilon " + fmt("%g", reference.epsilon);
    (*v)["alias_reference"] = sizeText(samples, samples) + " samples a pixel (aa " +
                              std::to_string(kAliasReferenceAa) + " at " +
                              std::to_string(kAliasReferenceScale) + "x the size, box-filtered)";
    (*v)["alias_size"] = sizeText(kAliasWidth, kAliasHeight);
    (*v)["draft_speedup"] = fmt("%gx", kDraftSpeedUp);
    (*v)["draft_db"] = fmt("%g dB", kDraftDb);
}

// Every measured section, in the order the report prints them.
void measureAll(Renderer& r, const std::string& root, const std::string& docs, TemplateValues* v) {
    std::cerr << "render report: uber against specialised\n";
    (*v)["uber_table"] = uberTable(r, root);
    std::cerr << "render report: object count\n";
    (*v)["scaling_table"] = scalingTable(r, root, docs);
    const std::vector<std::string> marched = {"default", "csg", "reflections", "pile"};
    (*v)["cost_table"] = costSection(r, marched, root);
    marchingSections(r, marched, root, docs, v);
    (*v)["aliasing_sections"] = aliasingSections(r, marched, root);
    (*v)["preset_settings"] = presetSettingsTable();
    (*v)["preset_table"] =
        presetSection(r, {"default", "csg", "reflections", "pile", "primitives", "fog"}, root);
    int passing = 0, scenes = 0;
    (*v)["draft_table"] = draftSection(r, root, &passing, &scenes);
    (*v)["draft_passing"] = std::to_string(passing);
    (*v)["draft_scenes"] = std::to_string(scenes);
    std::cerr << "render report: frame sequences\n";
    (*v)["sequence_table"] = sequenceSection(root);
}

}  // namespace

int runRenderReport(const std::string& root, OffscreenBackend backend) {
    OffscreenContext context;
    Renderer renderer;
    ColorTarget target;  // big enough for the 4x reference; EGL has no default framebuffer
    std::string error, text, docs = root + "/docs";
    if (!readReportTemplate(root, "render-report.md", &text, &error)) {
        std::cerr << error << '\n';
        return 1;
    }
    if (!context.create(1, 1, &error, backend) || !renderer.init(&error) ||
        !target.resize(4 * kWidth, 4 * kHeight, GL_RGBA8)) {
        std::cerr << "cannot render: " << error << '\n';
        return 3;
    }
    target.bind();
    std::filesystem::create_directories(docs);
    const std::string path = docs + "/render-report.md";
    std::string written;  // its device section is kept, or replaced alone
    readTextFile(path, &written);
    const std::string device = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    if (backend == OffscreenBackend::Egl) {  // the device's section alone
        std::cerr << "render report: " << device << " through EGL\n";
        const std::string section = deviceSection(root, device);
        if (section.empty()) {
            std::cerr << "cannot measure the device: no executable path or temporary folder\n";
            return 1;
        }
        if (!writeTextFile(path, withDeviceSection(written, section))) {
            std::cerr << "cannot write " << path << '\n';
            return 1;
        }
    } else {
        TemplateValues v = {{"platform", context.platform()},
                            {"gl_renderer", device},
                            {"machine", machineDescription()},
                            {"device_section", keptDeviceSection(written)}};
        describeMethod(&v);
        measureAll(renderer, root, docs, &v);
        if (!writeReport(path, text, v, &error)) {
            std::cerr << error << '\n';
            return 1;
        }
    }
    std::cout << "wrote " << path << '\n';
    return 0;
}

}  // namespace mb

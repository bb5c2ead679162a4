// Box2D 2.4.1 reference for the benchmark's box piles (src/Benchmarks/BoxPileScene.vb).
//
// Reads a pile written by the benchmark (one item per line, SI units, '#' starts a comment):
//     world <width> <height> <gravity> <restitution>
//     box <x of lower-left corner> <y of lower-left corner> <width> <height> <mass>
// and runs it in Box2D as the engine runs it: a walled container, boxes that never rotate
// (fixedRotation), friction 0, restitution e, at 60 Hz with 8 velocity and 3 position iterations,
// until every body sleeps (Box2D's own rest test: slower than b2_linearSleepTolerance for
// b2_timeToSleep) or a cap of simulated time. Box2D gives every polygon a rounded skin of
// b2_polygonRadius; the boxes and walls here are made that much smaller, so that the skin's outside
// is the box the engine collides.
//
// Prints one line per run, timed from the first step to the last (building the world is not timed):
//     run <k> steps=<n> simulated_s=<s> wall_ms=<ms> max_overlap_m=<m> asleep=<a> bodies=<n>
// max_overlap_m is the deepest overlap between two boxes, or a box and a wall, at the end, from the
// boxes' outlines (negative: the closest pair is that far apart).
//
// usage: box_pile SCENE [--runs K] [--cap SECONDS]     exit 0 on success, 2 on bad input
#include <box2d/box2d.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Box {
    double x, y, w, h, mass;  // lower-left corner (m), size (m), kg
};

struct Scene {
    double width = 0, height = 0, gravity = 0, restitution = 0;  // m, m, m/s², 1
    std::vector<Box> boxes;
};

bool ReadScene(const char* path, Scene& scene, std::string& why) {
    std::ifstream in(path);
    if (!in) {
        why = std::string("cannot read ") + path;
        return false;
    }
    std::string line;
    int number = 0;
    bool haveWorld = false;
    while (std::getline(in, line)) {
        ++number;
        auto hash = line.find('#');
        if (hash != std::string::npos) line.erase(hash);
        std::istringstream words(line);
        std::string kind;
        if (!(words >> kind)) continue;
        std::string rest;
        if (kind == "world") {
            if (!(words >> scene.width >> scene.height >> scene.gravity >> scene.restitution) || (words >> rest) ||
                scene.width <= 0 || scene.height <= 0) {
                why = std::string(path) + ":" + std::to_string(number) + ": expected 'world <width> <height> <gravity> <restitution>'";
                return false;
            }
            haveWorld = true;
        } else if (kind == "box") {
            Box b{};
            if (!(words >> b.x >> b.y >> b.w >> b.h >> b.mass) || (words >> rest) || b.w <= 0 || b.h <= 0 || b.mass <= 0) {
                why = std::string(path) + ":" + std::to_string(number) + ": expected 'box <x> <y> <width> <height> <mass>' with sizes and mass > 0";
                return false;
            }
            scene.boxes.push_back(b);
        } else {
            why = std::string(path) + ":" + std::to_string(number) + ": unknown item '" + kind + "' (expected world or box)";
            return false;
        }
    }
    if (!haveWorld) {
        why = std::string(path) + ": no 'world' line";
        return false;
    }
    return true;
}

// A box whose rounded skin (b2_polygonRadius) ends on the given outline.
b2PolygonShape SkinnedBox(double halfWidth, double halfHeight, b2Vec2 centre) {
    b2PolygonShape shape;
    shape.SetAsBox(float(halfWidth) - b2_polygonRadius, float(halfHeight) - b2_polygonRadius, centre, 0.0f);
    return shape;
}

struct RunResult {
    int steps = 0;
    double simulated = 0, wallMs = 0, maxOverlap = 0;
    int asleep = 0;
};

double Overlap(const Box& a, const Box& b) {
    double ox = std::min(a.x + a.w, b.x + b.w) - std::max(a.x, b.x);
    double oy = std::min(a.y + a.h, b.y + b.h) - std::max(a.y, b.y);
    return std::min(ox, oy);
}

RunResult Run(const Scene& scene, double cap) {
    const float dt = 1.0f / 60.0f;
    b2World world(b2Vec2(0.0f, -float(scene.gravity)));

    // The container: four walls 1 m thick outside it.
    b2BodyDef wallDef;
    b2Body* walls = world.CreateBody(&wallDef);
    const double W = scene.width, H = scene.height;
    b2FixtureDef wallFixture;
    wallFixture.friction = 0.0f;
    wallFixture.restitution = float(scene.restitution);
    b2PolygonShape floor = SkinnedBox(W / 2 + 1, 0.5, b2Vec2(float(W / 2), -0.5f));
    b2PolygonShape ceiling = SkinnedBox(W / 2 + 1, 0.5, b2Vec2(float(W / 2), float(H + 0.5)));
    b2PolygonShape left = SkinnedBox(0.5, H / 2 + 1, b2Vec2(-0.5f, float(H / 2)));
    b2PolygonShape right = SkinnedBox(0.5, H / 2 + 1, b2Vec2(float(W + 0.5), float(H / 2)));
    for (b2PolygonShape* s : {&floor, &ceiling, &left, &right}) {
        wallFixture.shape = s;
        walls->CreateFixture(&wallFixture);
    }

    std::vector<b2Body*> bodies;
    bodies.reserve(scene.boxes.size());
    for (const Box& b : scene.boxes) {
        b2BodyDef def;
        def.type = b2_dynamicBody;
        def.position.Set(float(b.x + b.w / 2), float(b.y + b.h / 2));
        def.fixedRotation = true;
        b2Body* body = world.CreateBody(&def);
        b2PolygonShape shape = SkinnedBox(b.w / 2, b.h / 2, b2Vec2(0.0f, 0.0f));
        b2FixtureDef fixture;
        fixture.shape = &shape;
        fixture.density = 1.0f;
        fixture.friction = 0.0f;
        fixture.restitution = float(scene.restitution);
        body->CreateFixture(&fixture);
        b2MassData mass;  // the box's own mass, whatever the skin leaves out
        mass.mass = float(b.mass);
        mass.center.SetZero();
        mass.I = 0.0f;
        body->SetMassData(&mass);
        bodies.push_back(body);
    }

    RunResult r;
    const int maxSteps = int(cap / dt + 0.5);
    auto start = std::chrono::steady_clock::now();
    for (;;) {
        world.Step(dt, 8, 3);
        ++r.steps;
        bool allAsleep = true;
        for (b2Body* body : bodies) {
            if (body->IsAwake()) {
                allAsleep = false;
                break;
            }
        }
        if (allAsleep || r.steps >= maxSteps) break;
    }
    auto end = std::chrono::steady_clock::now();
    r.wallMs = std::chrono::duration<double, std::milli>(end - start).count();
    r.simulated = r.steps * double(dt);

    std::vector<Box> now;
    for (size_t i = 0; i < bodies.size(); ++i) {
        const Box& b = scene.boxes[i];
        b2Vec2 c = bodies[i]->GetPosition();
        now.push_back(Box{c.x - b.w / 2, c.y - b.h / 2, b.w, b.h, b.mass});
        if (!bodies[i]->IsAwake()) ++r.asleep;
    }
    double worst = -1e300;
    for (size_t i = 0; i < now.size(); ++i) {
        const Box& a = now[i];
        worst = std::max({worst, -a.x, -a.y, a.x + a.w - W, a.y + a.h - H});
        for (size_t j = i + 1; j < now.size(); ++j) worst = std::max(worst, Overlap(a, now[j]));
    }
    r.maxOverlap = worst;
    return r;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: box_pile SCENE [--runs K] [--cap SECONDS]\n");
        return 2;
    }
    int runs = 1;
    double cap = 60.0;
    for (int i = 2; i < argc; ++i) {
        char* end = nullptr;
        if (std::strcmp(argv[i], "--runs") == 0 && i + 1 < argc) {
            long k = std::strtol(argv[++i], &end, 10);
            if (*end != '\0' || k < 1 || k > 1000) {
                std::fprintf(stderr, "box_pile: --runs: '%s' is not a whole number from 1 to 1000\n", argv[i]);
                return 2;
            }
            runs = int(k);
        } else if (std::strcmp(argv[i], "--cap") == 0 && i + 1 < argc) {
            cap = std::strtod(argv[++i], &end);
            if (*end != '\0' || !(cap > 0) || cap > 3600) {
                std::fprintf(stderr, "box_pile: --cap: '%s' is not a number of seconds from 0 to 3600\n", argv[i]);
                return 2;
            }
        } else {
            std::fprintf(stderr, "box_pile: unknown option '%s' (usage: box_pile SCENE [--runs K] [--cap SECONDS])\n", argv[i]);
            return 2;
        }
    }
    Scene scene;
    std::string why;
    if (!ReadScene(argv[1], scene, why)) {
        std::fprintf(stderr, "box_pile: %s\n", why.c_str());
        return 2;
    }
    for (const Box& b : scene.boxes) {
        if (b.w <= 2 * b2_polygonRadius || b.h <= 2 * b2_polygonRadius) {
            std::fprintf(stderr, "box_pile: a box of %g m x %g m is too small for Box2D's skin of %g m\n", b.w, b.h, double(b2_polygonRadius));
            return 2;
        }
    }
    for (int k = 1; k <= runs; ++k) {
        RunResult r = Run(scene, cap);
        std::printf("run %d steps=%d simulated_s=%.6f wall_ms=%.4f max_overlap_m=%.6e asleep=%d bodies=%zu\n", k, r.steps, r.simulated, r.wallMs,
                    r.maxOverlap, r.asleep, scene.boxes.size());
        std::fflush(stdout);
    }
    return 0;
}

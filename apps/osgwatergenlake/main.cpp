// osgwatergenlake: writes the demo lake as Wavefront OBJ + MTL + PNG textures, deterministically
// (same files on every run and machine). Sized like the thesis's scene (~131k vertices, ~85k faces):
// a basin with a deep centre and sloping shore, textured bed (sand, rock, weeds), grassy shore,
// rocks, trees above the water, a submerged crate, a post and a pier crossing the surface; a sky dome
// in its own file for scenes that want one (lake.osgt itself has the kit's clear sky, osgWater::Sky).
#include "LakeModel.h"
#include "ObjWriter.h"
#include <osgWater/Sky>
#include <osgWater/WaterNode>
#include <osg/ArgumentParser>
#include <osg/Image>
#include <osg/ProxyNode>
#include <osgDB/FileUtils>
#include <osgDB/WriteFile>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>

using lake::Random;

namespace {

const float kPi = 3.14159265f;

osg::Vec3 terrainNormal(float x, float y)
{
    const float e = 0.1f;
    osg::Vec3 n(lake::height(x - e, y) - lake::height(x + e, y), lake::height(x, y - e) - lake::height(x, y + e), 2 * e);
    n.normalize();
    return n;
}

bool writeTexture(const std::string& path, int w, int h, const std::function<osg::Vec3(int, int)>& f)
{
    osg::ref_ptr<osg::Image> img = new osg::Image;
    img->allocateImage(w, h, 1, GL_RGB, GL_UNSIGNED_BYTE);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const osg::Vec3 c = f(i, j);
            for (int k = 0; k < 3; ++k) img->data(i, j)[k] = (unsigned char)(std::min(std::max(c[k], 0.0f), 1.0f) * 255.0f + 0.5f);
        }
    return osgDB::writeImageFile(*img, path);
}

// value noise on a periodic lattice, so the textures tile
float noise(int i, int j, int period, uint64_t seed)
{
    auto lattice = [&](int a, int b) {
        Random r(seed + uint64_t(((a % period + period) % period) * 7919 + ((b % period + period) % period) * 104729));
        return r.uniform(0.0f, 1.0f);
    };
    const float cell = 128.0f / period;
    const float x = i / cell, y = j / cell;
    const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
    const float fx = x - x0, fy = y - y0;
    const float sx = fx * fx * (3 - 2 * fx), sy = fy * fy * (3 - 2 * fy);
    const float a = lattice(x0, y0), b = lattice(x0 + 1, y0), c = lattice(x0, y0 + 1), d = lattice(x0 + 1, y0 + 1);
    return (a * (1 - sx) + b * sx) * (1 - sy) + (c * (1 - sx) + d * sx) * sy;
}

float fbm(int i, int j, uint64_t seed) { return 0.5f * noise(i, j, 4, seed) + 0.3f * noise(i, j, 16, seed + 1) + 0.2f * noise(i, j, 64, seed + 2); }

bool writeTextures(const std::string& dir)
{
    bool ok = true;
    ok &= writeTexture(dir + "/sand.png", 128, 128, [](int i, int j) { const float n = fbm(i, j, 11); return osg::Vec3(0.80f, 0.70f, 0.48f) * (0.75f + 0.4f * n); });
    ok &= writeTexture(dir + "/rock.png", 128, 128, [](int i, int j) { const float n = fbm(i, j, 23); return osg::Vec3(0.42f, 0.40f, 0.38f) * (0.6f + 0.7f * n); });
    ok &= writeTexture(dir + "/grass.png", 128, 128, [](int i, int j) { const float n = fbm(i, j, 37); return osg::Vec3(0.26f, 0.52f, 0.16f) * (0.7f + 0.5f * n); });
    ok &= writeTexture(dir + "/mud.png", 128, 128, [](int i, int j) { const float n = fbm(i, j, 41); return osg::Vec3(0.36f, 0.33f, 0.22f) * (0.7f + 0.5f * n); });
    ok &= writeTexture(dir + "/bark.png", 64, 128, [](int i, int j) { const float n = noise(i * 8, j / 2, 16, 53); return osg::Vec3(0.36f, 0.24f, 0.13f) * (0.6f + 0.6f * n); });
    ok &= writeTexture(dir + "/leaves.png", 128, 128, [](int i, int j) { const float n = fbm(i * 2, j * 2, 61); return osg::Vec3(0.10f, 0.36f, 0.12f) * (0.55f + 0.8f * n); });
    ok &= writeTexture(dir + "/crate.png", 128, 128, [](int i, int j) {
        const float plank = (j / 16) % 2 ? 0.85f : 1.0f, n = noise(i / 4, j * 4, 16, 71);
        const bool edge = (i < 6 || i > 121 || j < 6 || j > 121);
        return (edge ? osg::Vec3(0.35f, 0.22f, 0.1f) : osg::Vec3(0.62f, 0.45f, 0.22f) * plank) * (0.8f + 0.3f * n); });
    ok &= writeTexture(dir + "/sky.png", 4, 128, [](int, int j) {
        const float t = j / 127.0f; // 0 at the horizon, 1 at the zenith
        return osg::Vec3(0.78f, 0.86f, 0.95f) * (1 - t) + osg::Vec3(0.32f, 0.52f, 0.86f) * t; });
    return ok;
}

bool writeMtl(const std::string& path)
{
    std::FILE* f = std::fopen(path.c_str(), "w");
    if (!f) return false;
    struct M { const char* name; float r, g, b; const char* map; bool emissive; };
    const M ms[] = { { "sand", 1, 1, 1, "sand.png", false }, { "rock", 1, 1, 1, "rock.png", false },
                     { "mud", 1, 1, 1, "mud.png", false },   { "grass", 1, 1, 1, "grass.png", false },
                     { "bark", 1, 1, 1, "bark.png", false }, { "leaves", 1, 1, 1, "leaves.png", false },
                     { "crate", 1, 1, 1, "crate.png", false }, { "post", 0.8f, 0.08f, 0.06f, nullptr, false },
                     { "wood", 0.55f, 0.40f, 0.25f, nullptr, false }, { "grassblade", 0.30f, 0.55f, 0.18f, nullptr, false },
                     { "weed", 0.22f, 0.38f, 0.12f, nullptr, false }, { "sky", 0, 0, 0, "sky.png", true } };
    std::fprintf(f, "# osgWater lake materials\n");
    for (const M& m : ms) {
        std::fprintf(f, "\nnewmtl %s\nKa %.3f %.3f %.3f\nKd %.3f %.3f %.3f\nKs 0 0 0\n", m.name, m.r, m.g, m.b, m.r, m.g, m.b);
        if (m.emissive) std::fprintf(f, "Ke 1 1 1\n");
        if (m.map) std::fprintf(f, "map_Kd %s\n", m.map);
    }
    std::fclose(f);
    return true;
}

void terrain(ObjWriter& obj, int n)
{
    std::vector<unsigned> idx(size_t(n) * n);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const float x = -0.5f * lake::kSize + lake::kSize * i / (n - 1), y = -0.5f * lake::kSize + lake::kSize * j / (n - 1);
            idx[size_t(j) * n + i] = obj.vertex(osg::Vec3(x, y, lake::height(x, y)), terrainNormal(x, y), osg::Vec2(x / 4.0f, y / 4.0f));
        }
    // one material per band of height: mud in the deep, rock on the steep middle, sand at the shore, grass above
    const char* names[] = { "mud", "rock", "sand", "grass" };
    for (int band = 0; band < 4; ++band) {
        obj.group(std::string("terrain_") + names[band], names[band]);
        for (int j = 0; j + 1 < n; ++j)
            for (int i = 0; i + 1 < n; ++i) {
                const float x = -0.5f * lake::kSize + lake::kSize * (i + 0.5f) / (n - 1);
                const float y = -0.5f * lake::kSize + lake::kSize * (j + 0.5f) / (n - 1);
                const float z = lake::height(x, y);
                const int b = z < -7.0f ? 0 : z < -2.5f ? 1 : z < 0.5f ? 2 : 3;
                if (b != band) continue;
                const unsigned a = idx[size_t(j) * n + i], c = idx[size_t(j) * n + i + 1], d = idx[size_t(j + 1) * n + i + 1], e = idx[size_t(j + 1) * n + i];
                obj.triangle(a, c, d);
                obj.triangle(a, d, e);
            }
    }
}

// thin tapered blades (4 vertices, 1 face each): grass on the shore, weeds on the bed
void blades(ObjWriter& obj, const char* name, const char* material, int count, float zmin, float zmax, float hmin, float hmax, uint64_t seed)
{
    obj.group(name, material);
    Random r(seed);
    int made = 0;
    for (int tries = 0; made < count && tries < count * 50; ++tries) {
        const float x = r.uniform(-62, 62), y = r.uniform(-62, 62);
        const float z = lake::height(x, y);
        if (z < zmin || z > zmax) continue;
        const float a = r.uniform(0, 2 * kPi), h = r.uniform(hmin, hmax), w = r.uniform(0.05f, 0.09f);
        const float lean = r.uniform(0.0f, 0.3f) * h;
        const osg::Vec3 side(std::cos(a) * w, std::sin(a) * w, 0), tip(-std::sin(a) * lean, std::cos(a) * lean, h);
        const osg::Vec3 base(x, y, z - 0.02f);
        osg::Vec3 nrm = side ^ tip;
        nrm.normalize();
        const unsigned v0 = obj.vertex(base - side, nrm, osg::Vec2(0, 0)), v1 = obj.vertex(base + side, nrm, osg::Vec2(1, 0));
        const unsigned v2 = obj.vertex(base + tip + side * 0.15f, nrm, osg::Vec2(1, 1)), v3 = obj.vertex(base + tip - side * 0.15f, nrm, osg::Vec2(0, 1));
        obj.quad(v0, v1, v2, v3);
        ++made;
    }
}

// a closed-side cylinder or cone frustum along z, `seg` segments
void frustum(ObjWriter& obj, const osg::Vec3& base, float r0, float r1, float h, int seg, float vRepeat)
{
    std::vector<unsigned> bottom, top;
    const float slope = (r0 - r1) / h;
    for (int k = 0; k <= seg; ++k) {
        const float a = 2 * kPi * k / seg;
        osg::Vec3 n(std::cos(a), std::sin(a), slope);
        n.normalize();
        bottom.push_back(obj.vertex(base + osg::Vec3(std::cos(a) * r0, std::sin(a) * r0, 0), n, osg::Vec2(float(k) / seg, 0)));
        top.push_back(obj.vertex(base + osg::Vec3(std::cos(a) * r1, std::sin(a) * r1, h), n, osg::Vec2(float(k) / seg, vRepeat)));
    }
    for (int k = 0; k < seg; ++k) obj.quad(bottom[k], bottom[k + 1], top[k + 1], top[k]);
}

void box(ObjWriter& obj, const osg::Vec3& lo, const osg::Vec3& hi)
{
    const osg::Vec3 n[6] = { { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 }, { 0, 0, -1 } };
    for (const osg::Vec3& d : n) {
        // the face's four corners, counter-clockwise seen from outside
        osg::Vec3 u = std::fabs(d.z()) > 0.5f ? osg::Vec3(1, 0, 0) : osg::Vec3(0, 0, 1);
        osg::Vec3 v = d ^ u;
        const osg::Vec3 c = (lo + hi) * 0.5f, e = (hi - lo) * 0.5f;
        auto corner = [&](float su, float sv) {
            const osg::Vec3 p = d + u * su + v * sv;
            return c + osg::Vec3(p.x() * e.x(), p.y() * e.y(), p.z() * e.z());
        };
        const unsigned a = obj.vertex(corner(-1, -1), d, osg::Vec2(0, 0)), b = obj.vertex(corner(1, -1), d, osg::Vec2(1, 0));
        const unsigned cc = obj.vertex(corner(1, 1), d, osg::Vec2(1, 1)), dd = obj.vertex(corner(-1, 1), d, osg::Vec2(0, 1));
        if (((u ^ v) * d) > 0) obj.quad(a, b, cc, dd);
        else obj.quad(a, dd, cc, b);
    }
}

void rock(ObjWriter& obj, const osg::Vec3& c, float radius, uint64_t seed)
{
    const int rings = 10, seg = 16;
    Random r(seed);
    std::vector<float> bump(size_t(rings + 1) * (seg + 1));
    for (float& b : bump) b = r.uniform(0.8f, 1.15f);
    for (int k = 0; k <= rings; ++k) bump[size_t(k) * (seg + 1) + seg] = bump[size_t(k) * (seg + 1)]; // close the seam
    for (int s = 0; s <= seg; ++s) { // one point at each pole
        bump[size_t(s)] = bump[0];
        bump[size_t(rings) * (seg + 1) + s] = bump[size_t(rings) * (seg + 1)];
    }
    std::vector<unsigned> id(bump.size());
    for (int k = 0; k <= rings; ++k)
        for (int s = 0; s <= seg; ++s) {
            const float th = kPi * k / rings, ph = 2 * kPi * s / seg;
            const osg::Vec3 n(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
            const float rr = radius * bump[size_t(k) * (seg + 1) + s];
            id[size_t(k) * (seg + 1) + s] = obj.vertex(c + osg::Vec3(n.x() * rr, n.y() * rr, n.z() * rr * 0.7f), n, osg::Vec2(2.0f * s / seg, 1.0f * k / rings));
        }
    for (int k = 0; k < rings; ++k)
        for (int s = 0; s < seg; ++s) {
            const unsigned a = id[size_t(k) * (seg + 1) + s], b = id[size_t(k) * (seg + 1) + s + 1];
            const unsigned cc = id[size_t(k + 1) * (seg + 1) + s + 1], d = id[size_t(k + 1) * (seg + 1) + s];
            obj.quad(a, d, cc, b);
        }
}

void skyDome(ObjWriter& obj, float radius)
{
    obj.group("sky", "sky");
    const int rings = 12, seg = 32;
    std::vector<unsigned> id;
    for (int k = 0; k <= rings; ++k)
        for (int s = 0; s <= seg; ++s) {
            const float el = (kPi / 2) * k / rings - 0.08f, az = 2 * kPi * s / seg; // a little below the horizon
            const osg::Vec3 d(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
            id.push_back(obj.vertex(d * radius, -d, osg::Vec2(float(s) / seg, std::max(0.0f, float(k) / rings))));
        }
    for (int k = 0; k < rings; ++k)
        for (int s = 0; s < seg; ++s) // seen from inside
            obj.quad(id[k * (seg + 1) + s], id[(k + 1) * (seg + 1) + s], id[(k + 1) * (seg + 1) + s + 1], id[k * (seg + 1) + s + 1]);
}

bool writeObj(const std::string& dir, int grid, int grassBlades, int weedBlades, unsigned& nv, unsigned& nf)
{
    ObjWriter obj(dir + "/lake.obj", "lake.mtl");
    if (!obj.ok()) return false;
    terrain(obj, grid);
    int t = 0;
    for (const lake::Tree& tr : lake::kTrees) {
        const osg::Vec3 base(tr.x, tr.y, lake::height(tr.x, tr.y) - 0.2f);
        obj.group("tree" + std::to_string(t) + "_trunk", "bark");
        frustum(obj, base, 0.35f, 0.22f, 0.55f * tr.height, 12, 4.0f);
        obj.group("tree" + std::to_string(t++) + "_crown", "leaves");
        for (int layer = 0; layer < 3; ++layer) {
            const float z0 = (0.3f + 0.2f * layer) * tr.height, r0 = (0.32f - 0.06f * layer) * tr.height;
            frustum(obj, base + osg::Vec3(0, 0, z0), r0, 0.02f, 0.45f * tr.height, 20, 2.0f);
        }
    }
    obj.group("rocks", "rock");
    Random r(303);
    for (int k = 0; k < 6; ++k) {
        const float a = 2 * kPi * k / 6 + 0.4f, rad = 39.0f + r.uniform(-3, 4);
        const float x = rad * std::cos(a), y = rad * std::sin(a) / std::sqrt(1.15f);
        rock(obj, osg::Vec3(x, y, lake::height(x, y)), r.uniform(0.8f, 1.8f), 400 + k);
    }
    obj.group("post", "post"); // crosses the water: tests clipping and the back faces of fig. 3
    const float pz = lake::height(lake::kPostX, lake::kPostY);
    box(obj, osg::Vec3(lake::kPostX - 0.2f, lake::kPostY - 0.2f, pz - 0.3f), osg::Vec3(lake::kPostX + 0.2f, lake::kPostY + 0.2f, 2.2f));
    obj.group("pier", "wood");
    box(obj, osg::Vec3(lake::kPierX1, lake::kPierY - 1.2f, 0.7f), osg::Vec3(lake::kPierX0, lake::kPierY + 1.2f, 0.9f));
    for (float x = lake::kPierX1 + 0.5f; x < lake::kPierX0; x += 4.0f)
        for (float side : { -1.0f, 1.0f }) {
            const float y = lake::kPierY + side * 1.0f;
            if (lake::height(x, y) > 0.4f) continue; // on land the deck rests on the ground
            box(obj, osg::Vec3(x - 0.15f, y - 0.15f, lake::height(x, y) - 0.3f), osg::Vec3(x + 0.15f, y + 0.15f, 0.7f));
        }
    obj.group("crate", "crate"); // submerged: visible only through the water
    const float cz = lake::height(lake::kCrateX, lake::kCrateY);
    box(obj, osg::Vec3(lake::kCrateX - 1.0f, lake::kCrateY - 0.8f, cz - 0.2f), osg::Vec3(lake::kCrateX + 1.0f, lake::kCrateY + 0.8f, cz + 1.2f));
    nv = obj.vertices();
    nf = obj.faces();
    // the blades in their own file: one face each, seen from both sides, so lake.osgt turns face
    // culling off for them (the refraction pass culls back faces, for the insides of clipped solids)
    ObjWriter thin(dir + "/blades.obj", "lake.mtl");
    if (!thin.ok()) return false;
    blades(thin, "grass", "grassblade", grassBlades, 0.35f, 2.5f, 0.25f, 0.6f, 101);
    blades(thin, "weeds", "weed", weedBlades, -4.5f, -0.6f, 0.3f, 1.1f, 202);
    nv += thin.vertices();
    nf += thin.faces();
    // the dome in its own file, not in lake.osgt (the clear sky is): a scene that adds it culls its
    // back faces, so that from outside (osgviewer's home view) it does not hide the lake
    ObjWriter sky(dir + "/sky.obj", "lake.mtl");
    if (!sky.ok()) return false;
    skyDome(sky, 110.0f);
    nv += sky.vertices();
    nf += sky.faces();
    return true;
}

bool writeOsgt(const std::string& path)
{
    osg::ref_ptr<osgWater::WaterNode> water = new osgWater::WaterNode;
    water->setName("lake");
    water->getSurface()->setSize(lake::kSize);
    // the default swell plus two short ripples: on a lake the ripples make the caustics (apex
    // curvature a k^2 ~ 1/m puts their focus 3-4 m down, in the shallows), and the caustics
    // texture resolves them at 512 texels over the lake (0.3 m)
    std::vector<osgWater::Wave> waves = osgWater::defaultWaves();
    for (const osg::Vec4& r : { osg::Vec4(0.2f, 0.98f, 1.2f, 0.03f), osg::Vec4(-0.95f, 0.31f, 0.9f, 0.025f) }) {
        osgWater::Wave w;
        w.direction.set(r.x(), r.y());
        w.direction.normalize();
        w.wavelength = r.z();
        w.amplitude = r.w();
        w.phase = 0.7f * float(waves.size());
        waves.push_back(w);
    }
    water->getSurface()->setWaves(waves);
    // drawn: a breeze over the lake (5 m/s, its fetch the lake's size); the sum of sines above
    // stays in the file for --waves sum
    water->getSurface()->setWaveModel(osgWater::WaterSurface::WAVES_WIND);
    water->getSettings()->setCausticsResolution(512);
    water->getSettings()->setPhotonGridSize(1024); // four photons per caustics texel, the settings' default ratio
    osg::ref_ptr<osg::ProxyNode> scene = new osg::ProxyNode;
    scene->setFileName(0, "lake/lake.obj");
    scene->setLoadingExternalReferenceMode(osg::ProxyNode::LOAD_IMMEDIATELY);
    water->addChild(scene.get());
    osg::ref_ptr<osg::ProxyNode> blades = new osg::ProxyNode;
    blades->setFileName(0, "lake/blades.obj");
    blades->setLoadingExternalReferenceMode(osg::ProxyNode::LOAD_IMMEDIATELY);
    blades->getOrCreateStateSet()->setMode(GL_CULL_FACE, osg::StateAttribute::OFF); // both sides, in every pass
    water->addChild(blades.get());
    // the clear sky, lit by the water's sun: the passes draw it, the water reflects it, and the
    // benchmark's reference takes it as the light of rays that meet nothing
    osg::ref_ptr<osgWater::Sky> sky = new osgWater::Sky;
    sky->setSunDirection(water->getSettings()->getSunDirection());
    water->addChild(sky.get());
    return osgDB::writeNodeFile(*water, path);
}

}

int main(int argc, char** argv)
{
    osg::ArgumentParser args(&argc, argv);
    std::string dir = "data/lake", osgt;
    int grid = 170, grass = 16000, weeds = 9000; // ~131k vertices, ~85k faces, as in the thesis
    args.read("--out", dir);
    args.read("--osgt", osgt);
    args.read("--grid", grid);
    args.read("--grass", grass);
    args.read("--weeds", weeds);
    if (args.read("-h") || args.read("--help")) {
        std::cout << "osgwatergenlake [--out dir] [--osgt file] [--grid n] [--grass n] [--weeds n]\n";
        return 0;
    }
    if (!osgDB::makeDirectory(dir)) {
        std::cerr << "error: cannot create " << dir << std::endl;
        return 1;
    }
    unsigned nv = 0, nf = 0;
    if (!writeTextures(dir) || !writeMtl(dir + "/lake.mtl") || !writeObj(dir, grid, grass, weeds, nv, nf)) {
        std::cerr << "error: cannot write the lake into " << dir << std::endl;
        return 1;
    }
    std::cout << "lake: " << nv << " vertices, " << nf << " faces in " << dir << "/lake.obj, blades.obj and sky.obj" << std::endl;
    if (!osgt.empty() && !writeOsgt(osgt)) {
        std::cerr << "error: cannot write " << osgt << std::endl;
        return 1;
    }
    return 0;
}

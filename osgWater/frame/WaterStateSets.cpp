#include "frame/WaterStateSets.h"
#include "surface/SpectralWaves.h"
#include <osgWater/WaterSettings>
#include <osgWater/WaterSurface>
#include "shaders/Shaders.h"
#include "frame/PassTable.h"
#include "frame/PassCamera.h"
#include "frame/SceneLighting.h"
#include "optics/VirtualVertices.h"
#include "caustics/ProceduralCaustics.h"
#include <osg/Material>
#include <osg/Texture2D>
#include <osg/Image>

using namespace osgWater;

namespace {

osg::Texture2D* whiteTexture()
{
    osg::ref_ptr<osg::Image> img = new osg::Image;
    img->allocateImage(1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE);
    unsigned char* p = img->data();
    p[0] = p[1] = p[2] = p[3] = 255;
    osg::Texture2D* t = new osg::Texture2D(img.get());
    t->setName("osgWater.white");
    // OSG's default wrap is GL_CLAMP, which blends in the black border at s,t = 0: the very
    // coordinate that geometry without texture coordinates samples
    t->setWrap(osg::Texture::WRAP_S, osg::Texture::CLAMP_TO_EDGE);
    t->setWrap(osg::Texture::WRAP_T, osg::Texture::CLAMP_TO_EDGE);
    t->setFilter(osg::Texture::MIN_FILTER, osg::Texture::NEAREST);
    t->setFilter(osg::Texture::MAG_FILTER, osg::Texture::NEAREST);
    return t;
}

}

WaterStateSets::WaterStateSets() : _programs(new ProgramLibrary)
{
    _scene = new osg::StateSet;
    _scene->setName("osgWater.scene");
    _scene->setAttribute(_programs->get("osgWater.scene", "scene.vert", "scene.frag"));
    // geometry without a texture samples this white texel; children's own textures override it
    _scene->setTextureAttribute(UNIT_BASE, whiteTexture());
    _scene->addUniform(new osg::Uniform("osgWater_BaseTexture", int(UNIT_BASE)));
    osg::ref_ptr<osg::Material> m = new osg::Material; // GL's default material, made explicit
    _scene->setAttribute(m.get());
    _scene->addUniform(new osg::Uniform("osgWater_SunColor", osg::Vec3f(1.0f, 1.0f, 1.0f)));
    _scene->addUniform(new osg::Uniform("osgWater_Ambient", osg::Vec3f(0.3f, 0.3f, 0.3f)));
    _scene->addUniform(new osg::Uniform("osgWater_Exposure", 1.0f)); // linear light times this, then encoded
    // the sun, fog, caustics and clip plane come from each pass's SceneLighting
    _scene->addUniform(new osg::Uniform("osgWater_CausticsTex", int(UNIT_CAUSTICS)));
    _scene->addUniform(new osg::Uniform("osgWater_SunDepth", int(UNIT_SUN_DEPTH)));
    _scene->addUniform(new osg::Uniform("osgWater_ReflectedCausticsTex", int(UNIT_REFLECTED_CAUSTICS)));
    _scene->addUniform(new osg::Uniform("osgWater_ReflectedSunDepth", int(UNIT_REFLECTED_SUN_DEPTH)));
    // the sun's colour and the ambient follow the settings, changed in the update traversal
    _scene->setDataVariance(osg::Object::DYNAMIC);

    _water = new osg::StateSet;
    _water->setName("osgWater.water");
    _water->setAttribute(_programs->get("osgWater.water", "water.vert", "water.frag"));
    _water->addUniform(new osg::Uniform("osgWater_ReflectionTex", int(UNIT_REFLECTION)));
    _water->addUniform(new osg::Uniform("osgWater_RefractionTex", int(UNIT_REFRACTION)));
    _water->addUniform(new osg::Uniform("osgWater_RefractionDepth", int(UNIT_REFRACTION_DEPTH)));
    _water->addUniform(new osg::Uniform("osgWater_ReflectionDepth", int(UNIT_REFLECTION_DEPTH)));
    _water->addUniform(new osg::Uniform("osgWater_EnvironmentTex", int(UNIT_ENVIRONMENT)));
    _water->setDataVariance(osg::Object::DYNAMIC);
    osg::ref_ptr<osg::Uniform> waves = new osg::Uniform(osg::Uniform::FLOAT_VEC4, "osgWater_Waves", WaterSurface::MAX_WAVES);
    osg::ref_ptr<osg::Uniform> phases = new osg::Uniform(osg::Uniform::FLOAT, "osgWater_WavePhases", WaterSurface::MAX_WAVES);
    _water->addUniform(waves.get());
    _water->addUniform(phases.get());
    const char* floats[] = { "osgWater_Level", "osgWater_PhotonExtinction", "osgWater_FresnelQ", "osgWater_ReflectionScale",
                             "osgWater_UnderwaterScale", "osgWater_ErrorBudget", "osgWater_WaveBound", "osgWater_GridCell" };
    for (const char* f : floats) _water->addUniform(new osg::Uniform(f, 0.0f));
    _water->addUniform(new osg::Uniform("osgWater_WaveCount", 0));
    _water->addUniform(new osg::Uniform("osgWater_SearchSteps", 3));
    _water->addUniform(new osg::Uniform("osgWater_IOR", osg::Vec2f(1.0f, 1.333f)));
    _water->addUniform(new osg::Uniform("osgWater_OneStep", osg::Vec2f(1.0f, 20.0f)));
    // the procedural caustics' sun-and-halo map (the caustics texture's path and the scene program's)
    const procedural::SunHalo halo;
    _water->addUniform(new osg::Uniform("osgWater_SunHalo", osg::Vec3f(float(halo.discRadius), float(halo.haloRadius),
                                                                        float(halo.haloLevel))));
    // the refraction pass's virtual vertices and the procedural caustics made per pixel follow the
    // waves: the scene program shares their inputs
    // the wind's waves: their cascades' texture and scales (set when the surface has them)
    _water->addUniform(new osg::Uniform("osgWater_WaveCascades", int(UNIT_WAVES)));
    _water->addUniform(new osg::Uniform("osgWater_WaveHeights", int(UNIT_WAVE_HEIGHTS)));
    _water->addUniform(new osg::Uniform(osg::Uniform::FLOAT_VEC4, "osgWater_Cascades", WaveCascades::CASCADES));
    _water->addUniform(new osg::Uniform("osgWater_CascadeCount", 0));
    _water->addUniform(new osg::Uniform("osgWater_CascadeTexels", 1.0f));
    _water->addUniform(new osg::Uniform("osgWater_UnresolvedSlopes", 0.0f));
    _water->addUniform(new osg::Uniform("osgWater_WaveJacobians", int(UNIT_WAVE_JACOBIANS)));
    _water->addUniform(new osg::Uniform("osgWater_ChoppyChord", 1.0f));
    for (const char* u : { "osgWater_Waves", "osgWater_WavePhases", "osgWater_WaveCount", "osgWater_Level", "osgWater_IOR",
                           "osgWater_PhotonExtinction", "osgWater_FresnelQ", "osgWater_SunHalo", "osgWater_WaveCascades", "osgWater_WaveHeights",
                           "osgWater_Cascades", "osgWater_CascadeCount", "osgWater_CascadeTexels", "osgWater_UnresolvedSlopes",
                           "osgWater_WaveJacobians", "osgWater_ChoppyChord" })
        _scene->addUniform(_water->getUniform(u));
    _scene->addUniform(new osg::Uniform("osgWater_MembraneCell", 1.0f));
    _water->addUniform(new osg::Uniform("osgWater_LookupPlanes", osg::Vec2f(1.0f, 1.0f)));
    _water->addUniform(new osg::Uniform("osgWater_WaterColor", osg::Vec3f()));
    _water->addUniform(_scene->getUniform("osgWater_Exposure"));
    _water->addUniform(new osg::Uniform("osgWater_SurfaceSquare", osg::Vec4f()));
    _water->addUniform(new osg::Uniform("osgWater_Extinction", osg::Vec3f()));

    _guest = new osg::StateSet;
    _guest->setName("osgWater.guest");
    _guest->setAttribute(_programs->get("osgWater.guest", "guest.vert", "guest.frag"));

    _surfaceBin = new osg::StateSet;
    _surfaceBin->setName("osgWater.surfaceBin");
    setUpPassBin(_surfaceBin.get(), PASS_SURFACE);
}

void WaterStateSets::applySettings(const WaterSettings& s, const WaterSurface& surface, DebugOutput debug)
{
    _scene->getUniform("osgWater_SunColor")->set(s.getSunColor());
    _scene->getUniform("osgWater_Ambient")->set(s.getAmbientColor());
    _scene->getUniform("osgWater_Exposure")->set(s.getExposure()); // the water's program shares it
    _scene->getUniform("osgWater_MembraneCell")->set(float(virtualvertices::membraneCellSize(surface)));

    osg::StateSet* w = _water.get();
    w->getUniform("osgWater_IOR")->set(osg::Vec2f(s.getAirIOR(), s.getWaterIOR()));
    w->getUniform("osgWater_WaterColor")->set(s.getBodyColor());
    w->getUniform("osgWater_Extinction")->set(s.getViewExtinction());
    w->getUniform("osgWater_PhotonExtinction")->set(photonExtinction(s));
    w->getUniform("osgWater_FresnelQ")->set(s.getFresnelModelExponent());
    w->getUniform("osgWater_ReflectionScale")->set(s.getReflectionScale());
    w->getUniform("osgWater_UnderwaterScale")->set(s.getUnderwaterLookupScale());
    w->getUniform("osgWater_SearchSteps")->set(s.getSearchSteps());
    w->setDefine("OSGWATER_SEARCH_STEPS", std::to_string(s.getSearchSteps()));
    w->getUniform("osgWater_ErrorBudget")->set(s.getErrorBudget());
    w->getUniform("osgWater_OneStep")->set(osg::Vec2f(s.getOneStepScale(), s.getOneStepMaxDepth()));
    w->getUniform("osgWater_Level")->set(float(surface.getLevel()));
    w->getUniform("osgWater_WaveBound")->set(surface.usesGrid() ? surface.getMaxAmplitude() : 0.0f);

    const std::vector<Wave>& waves = surface.getWaves();
    osg::Uniform* wu = w->getUniform("osgWater_Waves");
    for (unsigned int i = 0; i < WaterSurface::MAX_WAVES; ++i) {
        osg::Vec4f v;
        if (i < waves.size()) {
            const float k = float(waves[i].wavenumber());
            v.set(waves[i].direction.x() * k, waves[i].direction.y() * k, waves[i].amplitude, 0.0f);
        }
        wu->setElement(i, v);
    }
    w->getUniform("osgWater_WaveCount")->set(int(waves.size()));
    applyWind(surface.getSpectralWaves());

    const osg::Vec2f half(0.5f * surface.getSize(), 0.5f * surface.getSize());
    const osg::Vec2f lo = surface.getCenter() - half, hi = surface.getCenter() + half;
    w->getUniform("osgWater_SurfaceSquare")->set(osg::Vec4f(lo.x(), lo.y(), hi.x(), hi.y()));
    w->getUniform("osgWater_GridCell")->set(surface.getSize() / float(std::max(surface.getResolution(), 2u) - 1));
    setDefineIf(w, "OSGWATER_GRID", surface.usesGrid());
    setDefineIf(w, "OSGWATER_RINGS", surface.usesGrid() && surface.getMeshLayout() == WaterSurface::MESH_EYE_RINGS);
    w->setDefine("OSGWATER_REFRACTION", std::to_string(int(s.getRefractionLookup())));
    w->setDefine("OSGWATER_REFLECTION", std::to_string(int(s.getReflectionLookup())));
    w->setDefine("OSGWATER_FRESNEL", std::to_string(int(s.getFresnelModel())));
    _scene->setDefine("OSGWATER_FRESNEL", std::to_string(int(s.getFresnelModel()))); // procedural caustics per pixel
    w->setDefine("OSGWATER_UNDERWATER", std::to_string(int(s.getUnderwaterModel())));
    // the tone curve, wherever the view's colours are encoded (owDisplay): the scene, and the sky
    // under it, the water, the backdrop
    for (osg::StateSet* ss : { _scene.get(), w })
        ss->setDefine("OSGWATER_TONE", std::to_string(int(s.getToneCurve())));
    // OSGWATER_NO_REFLECTION / OSGWATER_NO_REFRACTION follow what ran (ViewPasses), not the
    // settings; OSGWATER_ENVIRONMENT the map in use (setEnvironmentMap())
    if (debug == DEBUG_NONE) w->removeDefine("OSGWATER_DEBUG");
    else w->setDefine("OSGWATER_DEBUG", std::to_string(int(debug)));
}

void WaterStateSets::applyWind(detail::SpectralWaves* wind)
{
    // every program that reads the waves (the water's, the scene's virtual vertices and procedural
    // caustics, the photons') lies under one of the two state sets
    for (osg::StateSet* ss : { _water.get(), _scene.get() }) {
        setDefineIf(ss, "OSGWATER_WIND", wind != nullptr);
        setDefineIf(ss, "OSGWATER_CHOPPY", wind && wind->choppy());
        if (wind) {
            ss->setTextureAttribute(UNIT_WAVES, wind->texture());
            ss->setTextureAttribute(UNIT_WAVE_HEIGHTS, wind->heightTexture());
        } else {
            ss->removeTextureAttribute(UNIT_WAVES, osg::StateAttribute::TEXTURE);
            ss->removeTextureAttribute(UNIT_WAVE_HEIGHTS, osg::StateAttribute::TEXTURE);
        }
        if (wind && wind->choppy()) ss->setTextureAttribute(UNIT_WAVE_JACOBIANS, wind->jacobianTexture());
        else ss->removeTextureAttribute(UNIT_WAVE_JACOBIANS, osg::StateAttribute::TEXTURE);
    }
    _water->getUniform("osgWater_ChoppyChord")->set(wind ? float(wind->choppyChord()) : 1.0f);
    osg::Uniform* scales = _water->getUniform("osgWater_Cascades");
    for (unsigned int c = 0; c < WaveCascades::CASCADES; ++c) scales->setElement(c, wind ? wind->cascadeScale(c) : osg::Vec4f());
    _water->getUniform("osgWater_CascadeCount")->set(wind ? int(wind->cascadeCount()) : 0);
    _water->getUniform("osgWater_CascadeTexels")->set(wind ? float(wind->textureSize()) : 1.0f);
    _water->getUniform("osgWater_UnresolvedSlopes")->set(wind ? float(wind->unresolvedSlopeVariance()) : 0.0f);
}

void WaterStateSets::applyTime(const WaterSurface& surface, double t)
{
    std::lock_guard<std::mutex> guard(_timeLock);
    if (detail::SpectralWaves* wind = surface.getSpectralWaves()) wind->applyTime(t);
    osg::Uniform* pu = _water->getUniform("osgWater_WavePhases");
    for (unsigned int i = 0; i < WaterSurface::MAX_WAVES; ++i)
        pu->setElement(i, surface.wrappedPhase(i, t));
}

void WaterStateSets::resizeGLObjectBuffers(unsigned int maxSize)
{
    _scene->resizeGLObjectBuffers(maxSize);
    _water->resizeGLObjectBuffers(maxSize);
    _guest->resizeGLObjectBuffers(maxSize);
    _surfaceBin->resizeGLObjectBuffers(maxSize);
    _programs->resizeGLObjectBuffers(maxSize);
}

void WaterStateSets::releaseGLObjects(osg::State* state) const
{
    _scene->releaseGLObjects(state);
    _water->releaseGLObjects(state);
    _guest->releaseGLObjects(state);
    _surfaceBin->releaseGLObjects(state);
    _programs->releaseGLObjects(state);
}

void WaterStateSets::setEnvironmentMap(osg::TextureCubeMap* map)
{
    osg::StateSet* w = _water.get();
    if (w->getTextureAttribute(UNIT_ENVIRONMENT, osg::StateAttribute::TEXTURE) == map) return;
    if (map) {
        w->setTextureAttribute(UNIT_ENVIRONMENT, map);
        w->setDefine("OSGWATER_ENVIRONMENT");
    } else {
        w->removeTextureAttribute(UNIT_ENVIRONMENT, osg::StateAttribute::TEXTURE);
        w->removeDefine("OSGWATER_ENVIRONMENT");
    }
}

void WaterStateSets::applyLookupPlanes(const osg::Vec2f& heightDepth)
{
    osg::Uniform* u = _water->getUniform("osgWater_LookupPlanes");
    osg::Vec2f now;
    u->get(now);
    if (now != heightDepth) u->set(heightDepth);
}

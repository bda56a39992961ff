#include "Hud.h"
#include <osgText/Text>
#include <osg/Geode>
#include <osg/Timer>
#include <cstdio>
#include <sstream>

using osgWater::WaterSettings;

std::string describeSettings(const WaterSettings& s)
{
    std::ostringstream o;
    o << "quality " << WaterSettings::qualityName(s.getQuality()) << ", refraction " << (!s.getRefractionEnabled() ? "off" : s.getRefractionLookup() == WaterSettings::ITERATIVE ||
                                                                         s.getRefractionLookup() == WaterSettings::BRACKETED
                                                                 ? std::string(WaterSettings::refractionLookupName(s.getRefractionLookup())) + "/" +
                                                                       std::to_string(s.getSearchSteps())
                                                                 : std::string(WaterSettings::refractionLookupName(s.getRefractionLookup())))
      << (s.getRefractionCameraRotation() ? (s.getRefractionCameraApparentEye() ? " apparent eye" : " rotated") : "") << ", reflection " << (s.getReflectionEnabled() ? WaterSettings::reflectionLookupName(s.getReflectionLookup()) : "off")
      << ", budget " << s.getErrorBudget() << " texels"
      << ", fresnel " << WaterSettings::fresnelModelName(s.getFresnelModel())
      << ", water ";
    if (s.getWaterModel() == WaterSettings::WATER_PER_CHANNEL) o << "per-channel";
    else o << "k " << s.getAttenuation();
    o << ", tex " << s.getReflectionTextureSize()
      << ", glow " << (s.getGlowEnabled() ? "on" : "off") << (s.getEnvironmentMapEnabled() ? ", environment" : "")
      << ", underwater " << WaterSettings::underwaterModelName(s.getUnderwaterModel());
    return o.str();
}

std::string describeSurface(const osgWater::WaterSurface& s)
{
    if (!s.usesGrid()) return "mesh user";
    std::ostringstream o;
    o << "mesh " << osgWater::WaterSurface::meshLayoutName(s.getMeshLayout()) << ", waves ";
    if (s.getWaveModel() == osgWater::WaterSurface::WAVES_WIND) o << "wind " << s.getWind().speed << " m/s";
    else o << "sum";
    return o.str();
}

std::string describeCaustics(const osgWater::WaterNode& water, const osgWater::ViewReport& report)
{
    const WaterSettings& s = *water.getSettings();
    if (!s.getCausticsEnabled()) return "off";
    std::ostringstream o;
    o << WaterSettings::causticsMethodName(s.getCausticsMethod()) << (s.getCausticsSupersampling() ? " 2x2" : "")
      << (s.getCausticsTileSize() > 0.0f ? " tiled" : "") << (s.getReflectiveCaustics() ? " + reflective" : "") << ", "
      << osgWater::causticsGatherLabel(water.getActiveCausticsGather())
      << (s.getCausticsGather() != WaterSettings::GATHER_AUTO ? ""
          : report.causticsGatherSettled ? " (auto)" : " (auto, timing)") << " " << s.getCausticsResolution()
      << "/" << s.getPhotonGridSize();
    return o.str();
}

namespace {

class HudUpdate : public osg::NodeCallback
{
public:
    HudUpdate(osgText::Text* text, osgWater::WaterNode* water, osg::Camera* camera)
        : _text(text), _water(water), _camera(camera) {}

    void operator()(osg::Node* node, osg::NodeVisitor* nv) override
    {
        // frame rate from the viewer's reference (wall-clock) time of successive frames
        const double now = nv->getFrameStamp() ? nv->getFrameStamp()->getReferenceTime() : 0.0;
        const double dt = now - _last;
        _last = now;
        if (dt > 0 && dt < 10.0) _fps = _fps <= 0 ? 1.0 / dt : 0.9 * _fps + 0.1 / dt;
        const osgWater::ViewReport r = _water->getViewReport(_camera.get());
        char fps[32] = "-- fps"; // until two frames have been seen
        if (_fps > 0) std::snprintf(fps, sizeof(fps), "%.1f fps", _fps);
        // a pass that did not run (or is not timed on its own: caustics made per pixel) has no time
        auto ms = [](double v) {
            char s[32] = "--";
            if (v >= 0.0) std::snprintf(s, sizeof(s), "%.2f ms", v);
            return std::string(s);
        };
        const std::string line = std::string(fps) + "   reflection " + ms(r.milliseconds[osgWater::PASS_REFLECTION]) +
                                 "   refraction " + ms(r.milliseconds[osgWater::PASS_REFRACTION]) + "   caustics " +
                                 ms(r.milliseconds[osgWater::PASS_PHOTONS]) + " (GPU)\n";
        _text->setText(line + describeSettings(*_water->getSettings()) + ", " +
                       describeSurface(*_water->getSurface()) + ", caustics " + describeCaustics(*_water, r) +
                       "\nkeys: r reflection  f refraction  t technique  e reflection lookup  +/- steps  m fresnel  o rotation  k caustics  g gather  a caustics mesh  x 2x2  y reflective  v environment  i surface mesh  w/W wind  j waves  u under water  n model  l glow  s stats  arrows move");
        traverse(node, nv);
    }

private:
    osg::ref_ptr<osgText::Text> _text;
    osg::ref_ptr<osgWater::WaterNode> _water;
    osg::observer_ptr<osg::Camera> _camera;
    double _last = 0.0;
    double _fps = 0.0;
};

}

osg::ref_ptr<osg::Camera> createHud(osgWater::WaterNode* water, osg::Camera* mainCamera, int width, int height)
{
    osg::ref_ptr<osg::Camera> hud = new osg::Camera;
    hud->setReferenceFrame(osg::Camera::ABSOLUTE_RF);
    hud->setProjectionMatrixAsOrtho2D(0, width, 0, height);
    hud->setViewMatrix(osg::Matrix::identity());
    hud->setClearMask(GL_DEPTH_BUFFER_BIT);
    hud->setRenderOrder(osg::Camera::NESTED_RENDER); // inline in the main camera: its FBO when headless
    hud->setAllowEventFocus(false);
    osg::ref_ptr<osgText::Text> text = new osgText::Text;
    text->setCharacterSize(14.0f);
    text->setPosition(osg::Vec3(10.0f, height - 22.0f, 0.0f));
    text->setColor(osg::Vec4(1.0f, 1.0f, 1.0f, 1.0f));
    text->setBackdropType(osgText::Text::DROP_SHADOW_BOTTOM_RIGHT);
    text->setDataVariance(osg::Object::DYNAMIC);
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(text.get());
    // the text has its own shaders; keep the kit's scene program out of it
    geode->getOrCreateStateSet()->setMode(GL_LIGHTING, osg::StateAttribute::OFF);
    hud->addChild(geode.get());
    hud->setUpdateCallback(new HudUpdate(text.get(), water, mainCamera));
    return hud;
}

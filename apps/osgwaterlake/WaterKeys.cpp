#include "WaterKeys.h"

using osgWater::WaterSettings;

bool WaterKeys::handle(const osgGA::GUIEventAdapter& ea, osgGA::GUIActionAdapter&)
{
    if (ea.getEventType() != osgGA::GUIEventAdapter::KEYDOWN) return false;
    WaterSettings& s = *_water->getSettings();
    switch (ea.getKey()) {
    case 'r': s.setReflectionEnabled(!s.getReflectionEnabled()); return true;
    case 'f': s.setRefractionEnabled(!s.getRefractionEnabled()); return true;
    case 't': // iterative -> plane offset -> bracketed -> virtual vertices -> one-step -> iterative (the enum's order)
        s.setRefractionLookup(WaterSettings::RefractionLookup((int(s.getRefractionLookup()) + 1) % (WaterSettings::VIRTUAL_VERTICES + 1)));
        return true;
    case 'e': // search -> offset -> plane -> search
        s.setReflectionLookup(s.getReflectionLookup() == WaterSettings::REFLECTION_SEARCH ? WaterSettings::REFLECTION_OFFSET
                              : s.getReflectionLookup() == WaterSettings::REFLECTION_OFFSET ? WaterSettings::REFLECTION_PLANE
                                                                                            : WaterSettings::REFLECTION_SEARCH);
        return true;
    case '+': case '=': s.setSearchSteps(std::min(s.getSearchSteps() + 1, 8)); return true;
    case '-': s.setSearchSteps(std::max(s.getSearchSteps() - 1, 1)); return true;
    case 'm': s.setFresnelModel(WaterSettings::FresnelModel((int(s.getFresnelModel()) + 1) % (WaterSettings::FRESNEL_RECIPROCAL + 1))); return true;
    case 'o': // rotated to the apparent eye -> the thesis's rigid rotation -> not rotated -> ...
        if (!s.getRefractionCameraRotation()) {
            s.setRefractionCameraRotation(true);
            s.setRefractionCameraApparentEye(true);
        } else if (s.getRefractionCameraApparentEye()) s.setRefractionCameraApparentEye(false);
        else s.setRefractionCameraRotation(false);
        return true;
    case 'k': s.setCausticsEnabled(!s.getCausticsEnabled()); return true;
    case 'l': s.setGlowEnabled(!s.getGlowEnabled()); return true;
    case 'n':
        s.setUnderwaterModel(s.getUnderwaterModel() == WaterSettings::UNDERWATER_PHYSICAL ? WaterSettings::UNDERWATER_THESIS
                                                                                    : WaterSettings::UNDERWATER_PHYSICAL);
        return true;
    case 'u': { // under water and back: to whichever view is further from where the camera is now
        osg::ref_ptr<osgGA::CameraManipulator> m;
        if (!_manipulator.lock(m)) return false;
        const osg::Vec3d now = m->getMatrix().getTrans();
        const bool goBelow = (now - _below.getTrans()).length2() > (now - _above.getTrans()).length2();
        m->setByMatrix(goBelow ? _below : _above);
        return true;
    }
    case 'g': // auto -> copy -> texture -> cpu -> auto
        s.setCausticsGather(WaterSettings::CausticsGather((int(s.getCausticsGather()) + 1) % 4));
        return true;
    case 'a': // photons -> area-ratio mesh -> procedural (texture) -> procedural (per pixel) -> photons
        s.setCausticsMethod(WaterSettings::CausticsMethod((int(s.getCausticsMethod()) + 1) % (WaterSettings::CAUSTICS_PROCEDURAL_SCREEN + 1)));
        return true;
    case 'x': s.setCausticsSupersampling(!s.getCausticsSupersampling()); return true;
    case 'y': s.setReflectiveCaustics(!s.getReflectiveCaustics()); return true;
    case 'v': s.setEnvironmentMapEnabled(!s.getEnvironmentMapEnabled()); return true;
    case 'j': { // the wind's waves <-> the sum of sines
        osgWater::WaterSurface& surface = *_water->getSurface();
        surface.setWaveModel(surface.getWaveModel() == osgWater::WaterSurface::WAVES_WIND ? osgWater::WaterSurface::WAVES_SUM
                                                                                       : osgWater::WaterSurface::WAVES_WIND);
        return true;
    }
    case 'w': case 'W': { // the wind one step up (w) or down (W): still, 2, 5, 8, 12, 20 m/s
        osgWater::WaterSurface& surface = *_water->getSurface();
        const float steps[] = { 0.0f, 2.0f, 5.0f, 8.0f, 12.0f, 20.0f };
        const int n = int(sizeof(steps) / sizeof(steps[0]));
        osgWater::WindWaves w = surface.getWind();
        int i = 0;
        while (i + 1 < n && steps[i] < w.speed) ++i; // the step at or above the wind now
        if (ea.getKey() == 'w') i = steps[i] > w.speed ? i : std::min(i + 1, n - 1);
        else i = std::max(i - 1, 0);
        w.speed = steps[i];
        surface.setWind(w);
        surface.setWaveModel(osgWater::WaterSurface::WAVES_WIND);
        return true;
    }
    case 'i': {
        osgWater::WaterSurface& surface = *_water->getSurface();
        surface.setMeshLayout(surface.getMeshLayout() == osgWater::WaterSurface::MESH_GRID
                                  ? osgWater::WaterSurface::MESH_EYE_RINGS : osgWater::WaterSurface::MESH_GRID);
        return true;
    }
    default: break;
    }
    auto toggle = _toggles.find(ea.getKey());
    if (toggle == _toggles.end() || toggle->second.props->getNumChildren() == 0) return false;
    osg::Switch* props = toggle->second.props.get();
    if (props->getValue(0)) props->setAllChildrenOff();
    else props->setAllChildrenOn();
    return true;
}

void WaterKeys::addToggle(int key, osg::Switch* props, const std::string& what)
{
    if (props) _toggles[key] = Toggle{ props, what };
}

bool WalkManipulator::handleKeyDown(const osgGA::GUIEventAdapter& ea, osgGA::GUIActionAdapter& aa)
{
    const double step = 0.5;
    switch (ea.getKey()) {
    case osgGA::GUIEventAdapter::KEY_Up: moveForward(step); break;
    case osgGA::GUIEventAdapter::KEY_Down: moveForward(-step); break;
    case osgGA::GUIEventAdapter::KEY_Left: moveRight(-step); break;
    case osgGA::GUIEventAdapter::KEY_Right: moveRight(step); break;
    case osgGA::GUIEventAdapter::KEY_Page_Up: moveUp(step); break;
    case osgGA::GUIEventAdapter::KEY_Page_Down: moveUp(-step); break;
    default: return osgGA::FirstPersonManipulator::handleKeyDown(ea, aa);
    }
    aa.requestRedraw();
    return true;
}

void WaterKeys::getUsage(osg::ApplicationUsage& u) const
{
    u.addKeyboardMouseBinding("r", "Toggle reflection");
    u.addKeyboardMouseBinding("f", "Toggle refraction");
    u.addKeyboardMouseBinding("t", "Next refraction lookup (iterative, plane offset, bracketed, virtual vertices, one-step)");
    u.addKeyboardMouseBinding("e", "Next reflection lookup (search, offset U + cR, plane offset)");
    u.addKeyboardMouseBinding("i", "Switch the surface's mesh (rings around the eye / the thesis's uniform grid)");
    u.addKeyboardMouseBinding("+/-", "More / fewer search steps");
    u.addKeyboardMouseBinding("m", "Next Fresnel model");
    u.addKeyboardMouseBinding("o", "Next refraction camera (apparent eye, the thesis's rotation, not rotated)");
    u.addKeyboardMouseBinding("k", "Toggle caustics");
    u.addKeyboardMouseBinding("g", "Next caustics gather (auto, copy, texture, CPU)");
    u.addKeyboardMouseBinding("a", "Next caustics method (photon splatting, area-ratio mesh, procedural in a texture, procedural per pixel)");
    u.addKeyboardMouseBinding("x", "Toggle caustics 2x2 supersampling");
    u.addKeyboardMouseBinding("y", "Toggle reflective caustics (the sun reflected onto what stands above the water)");
    u.addKeyboardMouseBinding("v", "Toggle the environment cube map");
    u.addKeyboardMouseBinding("u", "Go under water / back above it");
    u.addKeyboardMouseBinding("n", "Next underwater model (physical, thesis)");
    u.addKeyboardMouseBinding("l", "Toggle the sun's glow");
    for (const auto& t : _toggles) u.addKeyboardMouseBinding(std::string(1, char(t.first)), "Show / hide " + t.second.what);
    u.addKeyboardMouseBinding("Arrows, Page Up/Down", "Move the camera");
}

/* osgWater - natural water for OpenSceneGraph */
#ifndef OSGWATER_ENVIRONMENTMAP
#define OSGWATER_ENVIRONMENTMAP 1

#include <osgWater/Export>
#include "frame/PassCamera.h"
#include <osg/Group>
#include <osg/TextureCubeMap>
#include <map>

namespace osgWater {

//! The distant surroundings as a cube map (the DeepWater paper's environment map): the water's
//! scene above the water seen from the middle of the surface, six 90-degree faces (the pass
//! table's row PASS_ENVIRONMENT, shared by every view). The water reads it, in its local frame,
//! along reflected rays the reflection texture does not hold (and refracted rays from below that
//! find nothing in the refraction texture); the planar textures keep what is near.
//! It depends on the scene, not on the view or the waves: drawn once per context, and again only
//! when its centre, reach or sun changed, or after dirty().
class OSGWATER_EXPORT EnvironmentMap : public osg::Group
{
public:
    EnvironmentMap(osg::Group* scene, osg::StateSet* sceneState, int size);

    //! Where it is seen from and what it lights the scene with: the faces' matrices and lighting
    //! (everything above `lighting.level` is drawn), from `centre` out to the scene's bound.
    void aim(const osg::Vec3d& centre, const osg::BoundingSphere& scene, const SceneLighting& lighting);
    //! The colour where nothing is drawn: the views' background (a change draws the map again).
    void setBackground(const osg::Vec4& color);

    osg::TextureCubeMap* getTexture() const { return _cube.get(); }
    int getSize() const { return _size; }
    //! Whether the faces need drawing on a context (never drawn there, aimed anew or dirtied since,
    //! or the texture released).
    bool stale(unsigned int contextID) const;
    void markDrawn(unsigned int contextID) { _drawn[contextID] = _version; }
    //! Draw it again next frame (the scene changed).
    void dirty() { ++_version; }

    //! The view matrix of face `face` (osg::TextureCubeMap::POSITIVE_X ...) from `centre`, oriented
    //! as GL reads cube maps: the face's texel (s, t) lies along the direction GL maps to it.
    static osg::Matrixd faceView(int face, const osg::Vec3d& centre);

    void resizeGLObjectBuffers(unsigned int maxSize) override;
    void releaseGLObjects(osg::State* state = 0) const override;

protected:
    virtual ~EnvironmentMap() {}
    int _size;
    osg::ref_ptr<osg::TextureCubeMap> _cube;
    osg::ref_ptr<PassCamera> _faces[6];
    osg::Vec3d _centre;
    double _far = 0.0;
    osg::Vec3 _sun;
    osg::Vec4 _clearColor;
    unsigned int _version = 1;
    std::map<unsigned int, unsigned int> _drawn; // context -> version drawn
};

}

#endif

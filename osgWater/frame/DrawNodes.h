/* osgWater - natural water for OpenSceneGraph */
#ifndef OSGWATER_DRAWNODES
#define OSGWATER_DRAWNODES 1

#include <osgWater/Export>
#include <osg/Callback>
#include <osg/Group>
#include <osg/Plane>
#include <osg/StateSet>
#include <initializer_list>
#include <vector>

namespace osgUtil { class CullVisitor; }

namespace osgWater {

//! Pushes state sets on a cull visitor and pops them when it goes out of scope.
class OSGWATER_EXPORT ScopedStateSets
{
public:
    ScopedStateSets(osgUtil::CullVisitor& cv, std::initializer_list<osg::StateSet*> states);
    ~ScopedStateSets();
    ScopedStateSets(const ScopedStateSets&) = delete;
    ScopedStateSets& operator=(const ScopedStateSets&) = delete;
private:
    osgUtil::CullVisitor& _cv;
    unsigned int _pushed = 0;
};

//! The one cull callback of the kit's pass cameras: "draw these nodes under these state sets"
//! instead of the camera's children (the pattern of osgShadow's ViewDependentShadowMap: the
//! cameras stay out of the user's graph and traverse the water's scene themselves). A draw of a
//! group's children only is how a pass draws the WaterNode's scene (the WaterNode's own traverse
//! would start its passes again). An optional plane is added to the culling frustum, in the
//! camera's (absolute) reference frame, so subgraphs wholly on its other side are not traversed.
class OSGWATER_EXPORT DrawNodes : public osg::NodeCallback
{
public:
    //! Draw `node` under `states` (pushed in order), after the draws added before.
    void addNode(osg::Node* node, std::initializer_list<osg::StateSet*> states);
    //! Draw the children of `group`, which owns the camera (not held: it outlives it).
    void addChildrenOf(osg::Group* group, std::initializer_list<osg::StateSet*> states);
    //! Replace the node of draw `index` (a replaced water surface).
    void setNode(unsigned int index, osg::Node* node);

    void setCullingPlane(const osg::Plane& plane) { _plane = plane; _cullByPlane = true; }
    const osg::Plane& getCullingPlane() const { return _plane; }
    //! Whether the sides (and near and far) of the camera's frustum cull; without them only the
    //! culling plane does (a pass whose vertex shader moves geometry into the view from outside it).
    void setCullingByFrustum(bool on) { _cullByFrustum = on; }

    void operator()(osg::Node* camera, osg::NodeVisitor* nv) override;

    //! The held nodes and every state set of the draws (a group's children are its owner's to release).
    void resizeGLObjectBuffers(unsigned int maxSize) override;
    void releaseGLObjects(osg::State* state = 0) const override;

protected:
    struct Draw {
        osg::ref_ptr<osg::Node> node; // held
        osg::Group* childrenOf = nullptr;
        std::vector<osg::ref_ptr<osg::StateSet>> states;
    };
    std::vector<Draw> _draws;
    osg::Plane _plane;
    bool _cullByPlane = false;
    bool _cullByFrustum = true;
};

}

#endif

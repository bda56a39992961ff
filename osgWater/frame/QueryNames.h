/* osgWater - natural water for OpenSceneGraph */
#ifndef OSGWATER_QUERYNAMES
#define OSGWATER_QUERYNAMES 1

#include <osg/OcclusionQueryNode>
#include <osg/State>
#include <osg/buffered_value>

namespace osgWater {

//! Releases the GL query names a per-context record holds (its `ids`): OSG's query manager deletes
//! them in that context's next draw, and the record starts over (its owner makes new names when it
//! next draws there). With no state, every context's.
template <class PerContext>
void releaseQueryNames(osg::buffered_object<PerContext>& contexts, const osg::State* state)
{
    auto forget = [&contexts](unsigned int context) {
        for (unsigned int id : contexts[context].ids)
            if (id) osg::QueryGeometry::deleteQueryObject(context, id);
        contexts[context] = PerContext();
    };
    if (state) forget(state->getContextID());
    else
        for (unsigned int i = 0; i < contexts.size(); ++i) forget(i);
}

}

#endif

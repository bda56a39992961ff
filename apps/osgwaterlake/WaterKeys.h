// Keys that toggle each effect and switch technique (thesis §4.1: mouse and arrow keys move the camera).
#pragma once
#include <osgWater/WaterNode>
#include <osgGA/GUIEventHandler>
#include <osgGA/FirstPersonManipulator>
#include <osg/observer_ptr>
#include <osg/Switch>
#include <map>
#include <string>

//! Toggles water effects and techniques on key presses.
class WaterKeys : public osgGA::GUIEventHandler
{
public:
    explicit WaterKeys(osgWater::WaterNode* water) : _water(water) {}
    //! 'u' moves the camera between these two views (above the water, under it).
    void setViews(osgGA::CameraManipulator* manipulator, const osg::Matrixd& above, const osg::Matrixd& below)
    { _manipulator = manipulator; _above = above; _below = below; }
    //! `key` shows and hides the children of `props` ('b' the buoy and the boat, 'p' the pond).
    void addToggle(int key, osg::Switch* props, const std::string& what);
    bool handle(const osgGA::GUIEventAdapter& ea, osgGA::GUIActionAdapter& aa) override;
    void getUsage(osg::ApplicationUsage& usage) const override;

private:
    osg::ref_ptr<osgWater::WaterNode> _water;
    osg::observer_ptr<osgGA::CameraManipulator> _manipulator;
    struct Toggle { osg::ref_ptr<osg::Switch> props; std::string what; };
    std::map<int, Toggle> _toggles;
    osg::Matrixd _above, _below; // camera (inverse view) matrices
};

//! Mouse look (first person) plus the arrow keys and Page Up/Down to walk.
class WalkManipulator : public osgGA::FirstPersonManipulator
{
protected:
    bool handleKeyDown(const osgGA::GUIEventAdapter& ea, osgGA::GUIActionAdapter& aa) override;
};

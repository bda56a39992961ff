// Keys that toggle each effect and switch technique (thesis §4.1: mouse and arrow keys move the camera).
#pragma once
#include <osgWater/WaterNode>
#include <osgGA/GUIEventHandler>
#include <osgGA/FirstPersonManipulator>

//! Toggles water effects and techniques on key presses.
class WaterKeys : public osgGA::GUIEventHandler
{
public:
    explicit WaterKeys(osgWater::WaterNode* water) : _water(water) {}
    bool handle(const osgGA::GUIEventAdapter& ea, osgGA::GUIActionAdapter& aa) override;
    void getUsage(osg::ApplicationUsage& usage) const override;

private:
    osg::ref_ptr<osgWater::WaterNode> _water;
};

//! Mouse look (first person) plus the arrow keys and Page Up/Down to walk.
class WalkManipulator : public osgGA::FirstPersonManipulator
{
protected:
    bool handleKeyDown(const osgGA::GUIEventAdapter& ea, osgGA::GUIActionAdapter& aa) override;
};

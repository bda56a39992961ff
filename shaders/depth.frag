#version 130
// Depth-only passes write no colour (their targets have none).
void main()
{
}

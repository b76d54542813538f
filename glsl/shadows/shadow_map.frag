#version 330 core
// Shadow pass, 2D map: no colour. "The map is the depth buffer" (notes 01
// §8.5): the rasteriser writes each fragment's depth, glPolygonOffset's
// slope-scaled bias included.
void main() {}

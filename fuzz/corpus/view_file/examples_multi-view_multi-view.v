/* Two views side by side (LPFG manual 7.3): the model draws its leaves as
   lines in Stem and as spheres in Crown. Each view is written as a file of its
   own, at its window's share of the image size. */
window: Stem 0 0 0.5 1
window: Crown 0.5 0 0.5 1

#!/usr/bin/python3
"""A rendered PNG shows something: at least FRACTION of its pixels differ from the colour of its
top-left corner (the view's background).  Usage: check_png_shows_data.py PNG FRACTION"""
import sys

import matplotlib.image as mpimg
import numpy as np

img = mpimg.imread(sys.argv[1])[..., :3]
fraction = float(sys.argv[2])
differs = np.any(np.abs(img - img[0, 0]) > 1e-3, axis=-1).mean()
print(f"{sys.argv[1]}: {img.shape[1]} x {img.shape[0]} pixels, {100 * differs:.1f} % differ from the background "
      f"(at least {100 * fraction:.0f} % required)")
sys.exit(0 if differs >= fraction else 1)

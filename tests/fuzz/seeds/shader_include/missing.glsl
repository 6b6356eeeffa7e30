#version 450 core
  #  include   "nowhere.glsl"  

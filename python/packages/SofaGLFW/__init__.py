"""SofaGLFW: SOFA's GLFW GUI plugin. Sinew's viewer (Sofa.Gui, `sinew view`) is built in;
importing this module only checks that the scripts written for SOFA run unchanged."""

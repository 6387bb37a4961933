"""SofaImGui: SOFA's Dear ImGui GUI plugin. Sinew's viewer (Sofa.Gui, `sinew view`) is built in;
importing this module only checks that the scripts written for SOFA run unchanged."""

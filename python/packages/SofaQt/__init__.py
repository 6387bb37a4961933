"""SofaQt: SOFA's Qt GUI plugin. Sinew has no Qt GUI: its own viewer (Sofa.Gui, `sinew view`)
stands in for "qt" and "qglviewer", so that the scripts written for SOFA run unchanged."""

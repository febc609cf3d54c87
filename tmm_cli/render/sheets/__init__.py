"""The A1 drawing sheets 3 and 4: one ezdxf model per sheet, written as DXF and as a vector PDF."""

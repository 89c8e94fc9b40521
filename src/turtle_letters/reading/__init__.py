"""Reading letters from ink: its geometry, the forms letters take, the strokes' reader and OCR."""

#!/usr/bin/env python3
print("my controller")

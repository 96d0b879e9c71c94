## Schémas

schematic-title = Schéma
schematic-circuit = Circuit


## Esquemas

schematic-title = Esquema
schematic-circuit = Circuito


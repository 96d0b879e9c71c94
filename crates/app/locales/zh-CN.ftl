## 示意图

schematic-title = 示意图
schematic-circuit = 电路


### integrators

integrators-join = { "; " }
integrators-legend-dp45-order = DP45: { $order }
integrators-overflow-note = estouro em t = { $time }
integrators-failed = falhou
integrators-stable-yes = sim
integrators-stable-no = não
integrators-method-euler = Euler explícito
integrators-method-symplectic-euler = Euler simplético
integrators-method-heun = Heun
integrators-method-rk4 = RK4
integrators-legend-symplectic-euler = Euler simpl. ×
integrators-legend-dp45 = DP45 ● passos
integrators-legend-growing = { $legend } ×{ $growth }/passo ↑
integrators-legend-order = { $legend }: { $order }
integrators-legend-no-fit = { $legend }: sem ajuste
integrators-legend-dp45-no-order = DP45: sem ordem
integrators-series-exact = exata
integrators-axis-error = erro |x_num − x_exact|
integrators-axis-step = passo h
integrators-axis-max-error = erro máximo
integrators-axis-re = parte real Re(hλ)
integrators-axis-im = parte imaginária Im(hλ)
integrators-axis-evaluations = avaliações do lado direito N
integrators-limit-up-to = estável para h ≤ { $step }
integrators-limit-every = estável para todo h
integrators-limit-none = instável para todo h
integrators-method-overflows = { $method } estoura em t = { $time } (×{ $growth } por passo)
integrators-method-diverges = { $method } diverge (×{ $growth } por passo), erro máximo { $error }
integrators-method-diverges-clipped = { $method } diverge (×{ $growth } por passo, cortado), erro máximo { $error }
integrators-method-bounded = { $method } permanece limitado (×{ $growth } por passo), erro máximo { $error }
integrators-dp45-words = DP45 deu { $steps ->
        [one] { $steps } passo
       *[other] { $steps } passos
    } (tolerância { $tolerance }), erro máximo { $error }
integrators-dp45-failed = DP45 falhou: { $reason }
integrators-failed-underflow = o passo ficou pequeno demais para avançar em t = { $time } (o problema pode ser rígido demais ou singular)
integrators-failed-max-steps = desistiu em t = { $time } após { $steps } passos
integrators-failed-non-finite = a solução tornou-se infinita ou indefinida em t = { $time } (tente um passo menor)
integrators-describe-response = Cada método comparado com a oscilação amortecida exata ao longo de { $duration } com h = { $step } ({ $steps } passos). { $methods }. O gráfico mostra ±{ $range } vezes a amplitude exata; as curvas que passam disso são cortadas na borda.
integrators-describe-response-last = Cada método comparado com a oscilação amortecida exata ao longo de { $duration } com h = { $step } ({ $steps } passos, o último de { $last } para terminar em T). { $methods }. O gráfico mostra ±{ $range } vezes a amplitude exata; as curvas que passam disso são cortadas na borda.
integrators-error-peak = { $method }: máximo { $error } em t = { $time }
integrators-error-peak-growing = { $method }: máximo { $error } em t = { $time }, crescente
integrators-error-none = { $method }: nenhum erro finito
integrators-error-no-method = Nenhum método está ativado.
integrators-describe-error = Erro |x_num − x_exact| em escala logarítmica nos pontos da malha de cada método (h = { $step }): { $methods }.
integrators-describe-error-clipped = Erro |x_num − x_exact| em escala logarítmica nos pontos da malha de cada método (h = { $step }): { $methods }. Erros acima de { $clip } são cortados no topo.
integrators-fit = { $method }: inclinação ajustada { $slope } (h = { $from } … { $to })
integrators-fit-overflows = { $method }: inclinação ajustada { $slope } (h = { $from } … { $to }), estoura para h ≥ { $limit }
integrators-no-fit = { $method }: sem ajuste (poucos pontos na faixa assintótica)
integrators-no-fit-overflows = { $method }: sem ajuste (poucos pontos na faixa assintótica), estoura para h ≥ { $limit }
integrators-slope = inclinação { $order }
integrators-describe-convergence = Erro máximo em { $points } pontos de verificação comuns em função do passo h, para até { $levels } passos que se reduzem à metade a partir de { $from } (no máximo { $budget } passos por método no total, { $euler_budget } para Euler explícito; passos mais finos são omitidos). { $methods }. Cada ordem é ajustada apenas na faixa assintótica, desenhada como o segmento grosso: os passos mais finos cujas inclinações locais concordam dentro de { $spread }, com erros abaixo de { $ceiling } e acima de 1e-10 de x₀. As inclinações de referência 1 e 4 são pontilhadas; o h atual é a linha vertical tracejada. DP45 não tem um único h: veja o gráfico de trabalho–precisão.
integrators-off-scale = { $name } = { $value } (fora da escala)
integrators-path = hλ à medida que h cresce
integrators-z-real-pair = z = hλ = { $z1 } e { $z2 }
integrators-region-inside = { $method }: dentro da sua região, |R| = { $growth }, { $limit }
integrators-region-outside = { $method }: fora da sua região, |R| = { $growth }, { $limit }
integrators-describe-stability = Regiões de estabilidade |R(z)| ≤ 1 no plano complexo de z = hλ (o interior de cada curva fechada; a de Euler explícito é o disco |1 + z| ≤ 1). Os dois polos do sistema com h = { $step } dão { $z }. { $methods }. Euler simplético não é uma aplicação escalar R(z): sua matriz de passo 2×2 tem aqui raio espectral { $radius }, { $limit }. DP45 escolhe os próprios passos e os mantém estáveis.
integrators-work-words = { $method }: de { $error_first } com { $work_first } avaliações a { $error_last } com { $work_last }
integrators-describe-work = Erro máximo em função do trabalho que custou, contado em avaliações do lado direito f, em eixos log–log, para cada método: os de passo fixo nos passos do estudo de convergência (erro nos seus pontos de verificação comuns), DP45 nas tolerâncias { $from } … { $to } (erro nos seus passos aceitos). Mais abaixo é mais preciso, mais à esquerda é mais barato; um método de ordem p cai com inclinação −p; as execuções do DP45 são pontos onde a tolerância define os passos e cruzes onde a estabilidade os define. { $methods }.
integrators-dp45-stability-runs = execuções cujos passos a estabilidade define (mais de { $share } dos passos a { $fraction } ou mais do seu maior passo estável): { $count }/{ $runs }
integrators-dp45-order = DP45: ordem observada { $order } (ajustada em { $from } … { $to } avaliações, onde a tolerância define os passos); { $runs }
integrators-dp45-no-order = DP45 não tem ordem observada: a estabilidade define seus passos, ou restam poucas execuções na faixa assintótica; { $runs }
integrators-title = Integradores numéricos e seu erro
integrators-summary = O oscilador livre integrado por Euler explícito, Euler simplético, Heun (RK2) e RK4 clássico com passo fixo h, e por Dormand–Prince 5(4) com passo adaptativo, cada um comparado com a solução exata. Um método de passo único multiplica cada modo por R(hλ) a cada passo: quando |R| > 1, os números crescem por melhor que o método aproxime a equação, e é por isso que Euler explícito faz explodir um oscilador pouco amortecido a menos que h < 2ζ/ωₙ. Quando ele é estável, reduzir h à metade divide o erro por 2^p, onde p é a ordem de convergência do método: o gráfico de convergência mede p. Desativar um método oculta suas curvas; suas leituras continuam sendo calculadas.
integrators-param-zeta = razão de amortecimento
integrators-param-wn = frequência natural
integrators-param-h = passo
integrators-param-T = duração
integrators-param-x0 = deslocamento inicial
integrators-param-tol = tolerância do DP45 (relativa; absoluta tol·x₀)
integrators-param-euler = Euler explícito
integrators-param-symplectic-euler = Euler simplético
integrators-param-heun = Heun (RK2)
integrators-param-rk4 = RK4
integrators-param-dp45 = Dormand–Prince 5(4), adaptativo
integrators-readout-h-used = passo usado: exatamente h (um último passo mais curto termina a execução em T)
integrators-readout-h-last = último passo, que termina a execução em T
integrators-readout-max-err-euler = erro máximo, Euler explícito
integrators-readout-max-err-symplectic-euler = erro máximo, Euler simplético
integrators-readout-max-err-heun = erro máximo, Heun
integrators-readout-max-err-rk4 = erro máximo, RK4
integrators-readout-max-err-dp45 = erro máximo, DP45
integrators-readout-order-euler = ordem ajustada, Euler explícito
integrators-readout-order-symplectic-euler = ordem ajustada, Euler simplético
integrators-readout-order-heun = ordem ajustada, Heun
integrators-readout-order-rk4 = ordem ajustada, RK4
integrators-readout-order-dp45 = ordem observada, DP45 (erro em função das avaliações de f, onde a tolerância define os passos)
integrators-readout-stable-euler = estável com este h, Euler explícito
integrators-readout-stable-symplectic-euler = estável com este h, Euler simplético
integrators-readout-stable-heun = estável com este h, Heun
integrators-readout-stable-rk4 = estável com este h, RK4
integrators-readout-growth-euler = crescimento por passo |R(hλ)|, Euler explícito
integrators-readout-growth-symplectic-euler = crescimento por passo (raio espectral), Euler simplético
integrators-readout-growth-heun = crescimento por passo |R(hλ)|, Heun
integrators-readout-growth-rk4 = crescimento por passo |R(hλ)|, RK4
integrators-readout-steps-dp45 = passos aceitos pelo DP45
integrators-plot-response = Soluções numéricas e a x(t) exata
integrators-plot-error = Erro ao longo do tempo
integrators-plot-convergence = Convergência: erro máximo em função do passo h
integrators-plot-work = Trabalho–precisão: erro máximo em função das avaliações de f
integrators-plot-stability = Regiões de estabilidade e z = hλ
integrators-preset-1 = Pouco amortecido, h = 0,3 s
integrators-preset-2 = Euler no limite da estabilidade, h = 0,04 s
integrators-preset-3 = RK4 além do seu limite, h = 1,6 s
integrators-preset-4 = Não amortecido, h = 0,1 s
integrators-preset-5 = Rígido e superamortecido ζ = 2, ωₙ = 20
integrators-table-caption = Os métodos
integrators-table-column-1 = método
integrators-table-column-2 = ordem p
integrators-table-column-3 = avaliações de f por passo
integrators-table-column-4 = fator de amplificação R(z)
integrators-table-column-5 = num oscilador não amortecido
integrators-table-euler-1 = Euler explícito
integrators-table-euler-2 = 1
integrators-table-euler-3 = 1
integrators-table-euler-4 = 1 + z
integrators-table-euler-5 = sempre cresce: |R(iωh)| = √(1 + ω²h²) > 1
integrators-table-symplectic-euler-1 = Euler simplético
integrators-table-symplectic-euler-2 = 1
integrators-table-symplectic-euler-3 = 2
integrators-table-symplectic-euler-4 = matriz 2×2, não um R escalar
integrators-table-symplectic-euler-5 = erro de energia limitado enquanto ωh ≤ 2
integrators-table-heun-1 = Heun (RK2)
integrators-table-heun-2 = 2
integrators-table-heun-3 = 2
integrators-table-heun-4 = 1 + z + z²/2
integrators-table-heun-5 = cresce lentamente: |R(iy)|² = 1 + y⁴/4
integrators-table-rk4-1 = RK4 clássico
integrators-table-rk4-2 = 4
integrators-table-rk4-3 = 4
integrators-table-rk4-4 = 1 + z + z²/2 + z³/6 + z⁴/24
integrators-table-rk4-5 = amortece levemente enquanto ωh ≤ 2√2
integrators-table-dp45-1 = Dormand–Prince 5(4)
integrators-table-dp45-2 = 5
integrators-table-dp45-3 = 6 (a primeira igual à última)
integrators-table-dp45-4 = adaptativo: h segue a estimativa de erro
integrators-table-dp45-5 = estável: passos rejeitados reduzem h


### paper

paper-unavailable = a demonstração desta figura não está disponível
paper-figure = Figura { $number }
paper-section = Seção { $number }
paper-section-figure = Seção { $section }, figura { $figure }
paper-near-agrees = A demonstração calcula { $computed }, que coincide, dentro do arredondamento, com o valor do artigo, { $claimed } (tolerância ±{ $tolerance }).
paper-near-differs = A demonstração calcula { $computed }, e não o valor do artigo, { $claimed } (tolerância ±{ $tolerance }).
paper-below-agrees = A demonstração calcula { $computed }, abaixo do limite de { $bound } dado pelo artigo.
paper-below-differs = A demonstração calcula { $computed }, acima do limite de { $bound } dado pelo artigo.
paper-range = { $low } a { $high }
paper-range-agrees = A demonstração calcula de { $low } a { $high }, como diz o artigo.
paper-range-differs = A demonstração calcula de { $low } a { $high }, e não o intervalo do artigo.
paper-peak = O máximo de |H(r)| encontrado por busca está em r = { $found }, onde a fórmula dá { $formula }.
paper-slope = Com o passo do artigo, h = { $step }, e cinco reduções à metade (até { $smallest }), a inclinação ajustada é { $slope }.
paper-reason-context = { $verdict } { $context }
paper-exhibit-fig1a = Resposta livre do quarto de carro (m = 300 kg, k = 24 kN/m, x₀ = 60 mm) com os ajustes de conforto, desempenho, crítico e superamortecido.
paper-exhibit-fig1b = Tempo de acomodação em função da razão de amortecimento, com seu mínimo.
paper-exhibit-fig2a = Corrente no circuito RLC série (L = 0,5 H, C = 20 mF, V₀ = 12 V) à medida que a resistência percorre os regimes.
paper-exhibit-fig2b = Tensão no capacitor do mesmo circuito.
paper-exhibit-fig3a = Módulo da resposta em frequência para uma família de razões de amortecimento.
paper-exhibit-fig3b = Fase da resposta em frequência.
paper-exhibit-fig4a = Euler e RK4 comparados à resposta exata de um oscilador levemente amortecido (ζ = 0,05, ωₙ = 2 rad/s) com h = 0,3 s.
paper-exhibit-fig4b = Erro máximo em função do passo em eixos log–log, com as inclinações.
paper-exhibit-fig5 = Uma equação em muitas máquinas: sistemas mecânicos, elétricos e outros regidos pela mesma equação a·y'' + b·y' + c·y = f(t).
paper-exhibit-table1 = A analogia mecânico–elétrica: massa ↔ indutância, amortecedor ↔ resistência, mola ↔ 1/capacitância.
paper-exhibit-table2 = Os regimes de amortecimento: condição, raízes, comportamento e exemplos.
paper-exhibit-table3 = Os métodos de integração comparados: erro, ordem e estabilidade com um mesmo passo.
paper-claim-fig1-zeta-optimum = Uma razão de amortecimento de cerca de 0,7 dá o menor tempo de acomodação (faixa de 5 %).
paper-claim-sec3-natural-frequency = A frequência natural do quarto de carro é de cerca de 8,9 rad/s (cerca de 1,4 Hz).
paper-claim-sec4-critical-resistance = O circuito é criticamente amortecido com R = 2√(L/C) = 10 Ω.
paper-claim-fig3-q-factor = Q = 10 com ζ = 0,05.
paper-claim-fig3-q-factor-light = Q = 50 com ζ = 0,01.
paper-claim-sec5-peak-frequency = A resposta atinge o pico em ω = ωₙ√(1 − 2ζ²), logo abaixo de ωₙ (verificado com ζ = 0,1).
paper-claim-fig4-euler-error = Com h = 0,3 s, o erro máximo de Euler é de cerca de 0,08.
paper-claim-fig4-rk4-error = Com h = 0,3 s, o erro máximo do RK4 é menor que 0,001.
paper-claim-fig4-euler-slope = O erro de Euler cai com inclinação ≈ 1 no gráfico log–log.
paper-claim-sec7-mass-tolerance = Uma incerteza de ±10 % na massa suspensa leva ζ = 1,0 a um valor entre 0,91 e 1,10.
paper-claim-fig1-zeta-optimum-context = Para uma faixa de 2 %, o ζ de acomodação mais rápida passa a ser { $value }.
paper-claim-sec3-natural-frequency-context = Em hertz: fₙ = { $value }.
paper-claim-fig4-euler-error-context = Euler é instável com este passo: |1 + hλ| = { $value } por passo, então seu erro cresce sem limite.
paper-claim-fig4-rk4-error-context = O RK4 é estável com este passo (|R(hλ)| = { $value } por passo), mas ao longo de toda a janela seu erro excede o limite.
paper-claim-fig4-euler-slope-context = A ordem ajustada com passos pequenos, onde o erro é assintótico, é { $value }.
paper-claim-sec7-mass-tolerance-context = ζ = c/(2√(km)) varia como 1/√m, então uma variação de ±10 % na massa o altera apenas cerca de ±5 % (ωₙ cai para { $value } com +10 %).
paper-title = O artigo, verificado
paper-summary = O Zeta Lab foi construído a partir de um artigo sobre equações diferenciais de segunda ordem em sistemas mecânicos e elétricos (Ihenacho, Samuel, Okechukwu et al., Science Publishing Group, 2026). Aqui estão todas as suas figuras e tabelas, desenhadas ao vivo pela demonstração que as reproduz, e todos os números que ele afirma, verificados: cada afirmação mostra o valor do artigo, o valor que o aplicativo calcula e um veredito. Siga um link para abrir a demonstração exatamente nesse estado.
paper-readout-claims = afirmações verificadas
paper-readout-confirmed = afirmações confirmadas
paper-readout-differs = afirmações que divergem
paper-plot-fig1a = Figura 1(a)
paper-plot-fig1b = Figura 1(b)
paper-plot-fig2a = Figura 2(a)
paper-plot-fig2b = Figura 2(b)
paper-plot-fig3a = Figura 3(a)
paper-plot-fig3b = Figura 3(b)
paper-plot-fig4a = Figura 4(a)
paper-plot-fig4b = Figura 4(b)
paper-plot-fig5 = Figura 5
paper-plot-table1 = Tabela 1
paper-plot-table2 = Tabela 2
paper-plot-table3 = Tabela 3
